// Per-instance data: the affine rows of the model matrix, three texels an instance in the frame's instance buffer,
// read by instance index ("vertex pulling") rather than as instanced vertex attributes: on NVIDIA's hardware each
// instanced attribute costs a fetch per instance that pulling does not (a small mesh drawn 100k times: 2.1x faster
// pulled; benchmarks page, "Instance rows: pulled, not attributes"). The texture buffer is bound by the engine at a
// unit of its own; u_first_instance is the draw's first row (gl_InstanceID counts from 0 in every draw).
uniform samplerBuffer u_instance_rows;
uniform int u_first_instance;

vec4 instance_row(int k) {
    return texelFetch(u_instance_rows, (u_first_instance + gl_InstanceID) * 3 + k);
}

mat4 instance_model() {
    // GLSL matrices are built from columns: transpose the rows.
    return transpose(mat4(instance_row(0), instance_row(1), instance_row(2), vec4(0.0, 0.0, 0.0, 1.0)));
}

// The normal matrix as the cofactor matrix of the model's 3x3 part: proportional to the inverse
// transpose, finite even for zero scale, and cheap (three cross products). The columns are first
// divided by their largest component (no squares: they would underflow), so scales from 1e-30 to
// 1e30 keep their normals.
vec3 instance_normal(vec3 n) {
    mat3 m = mat3(instance_model());
    vec3 a = max(max(abs(m[0]), abs(m[1])), abs(m[2]));
    float s = max(max(a.x, a.y), a.z);
    if (s > 0.0) { m /= s; }
    vec3 c0 = m[0], c1 = m[1], c2 = m[2];
    mat3 cofactor = mat3(cross(c1, c2), cross(c2, c0), cross(c0, c1));
    float handedness = dot(c0, cross(c1, c2)) < 0.0 ? -1.0 : 1.0;
    vec3 r = cofactor * n * handedness;
    float len = length(r);
    return len > 1e-30 ? r / len : vec3(0.0, 1.0, 0.0);
}
