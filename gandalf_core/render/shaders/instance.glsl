// Per-instance data: the affine rows of the model matrix (locations 5..7), and helpers to use them.
layout(location = 5) in vec4 i_model_row0;
layout(location = 6) in vec4 i_model_row1;
layout(location = 7) in vec4 i_model_row2;

mat4 instance_model() {
    // GLSL matrices are built from columns: transpose the rows.
    return transpose(mat4(i_model_row0, i_model_row1, i_model_row2, vec4(0.0, 0.0, 0.0, 1.0)));
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
