// Per-instance data: the affine rows of the model matrix, three vec4 an instance in the frame's instance buffer
// (group 0, binding 4), read by instance index ("vertex pulling") rather than as instanced vertex attributes: on
// NVIDIA's hardware each instanced attribute costs a fetch per instance that pulling does not (a small mesh drawn
// 100k times: 2.1x faster pulled; benchmarks page, "Instance rows: pulled, not attributes"). A vertex entry point
// takes an `inst: Instance` parameter and hands it to the helpers; the draw's first instance is in the index.
@group(0) @binding(4) var<storage, read> gandalf_instance_rows: array<vec4<f32>>;

struct Instance {
    @builtin(instance_index) index: u32,
};

fn instance_row(inst: Instance, k: u32) -> vec4<f32> {
    return gandalf_instance_rows[inst.index * 3u + k];
}

fn instance_model(inst: Instance) -> mat4x4<f32> {
    // WGSL matrices are built from columns: transpose the rows.
    return transpose(mat4x4<f32>(instance_row(inst, 0u), instance_row(inst, 1u), instance_row(inst, 2u),
                                 vec4<f32>(0.0, 0.0, 0.0, 1.0)));
}

// The normal matrix as the cofactor matrix of the model's 3x3 part: proportional to the inverse
// transpose, finite even for zero scale, and cheap (three cross products). The columns are first
// divided by their largest component (no squares: they would underflow), so scales from 1e-30 to
// 1e30 keep their normals.
fn instance_normal(inst: Instance, n: vec3<f32>) -> vec3<f32> {
    let m = instance_model(inst);
    let a = max(max(abs(m[0].xyz), abs(m[1].xyz)), abs(m[2].xyz));
    let largest = max(max(a.x, a.y), a.z);
    let s = select(1.0, 1.0 / largest, largest > 0.0);
    let c0 = m[0].xyz * s;
    let c1 = m[1].xyz * s;
    let c2 = m[2].xyz * s;
    let cofactor = mat3x3<f32>(cross(c1, c2), cross(c2, c0), cross(c0, c1));
    let handedness = select(1.0, -1.0, dot(c0, cross(c1, c2)) < 0.0);
    let r = cofactor * n * handedness;
    let len = length(r);
    return select(vec3<f32>(0.0, 1.0, 0.0), r / len, len > 1e-30);
}
