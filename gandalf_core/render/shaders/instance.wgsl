// Per-instance data: the affine rows of the model matrix (locations 5..7), and helpers to use them.
struct Instance {
    @location(5) row0: vec4<f32>,
    @location(6) row1: vec4<f32>,
    @location(7) row2: vec4<f32>,
};

fn instance_model(inst: Instance) -> mat4x4<f32> {
    // WGSL matrices are built from columns: transpose the rows.
    return transpose(mat4x4<f32>(inst.row0, inst.row1, inst.row2, vec4<f32>(0.0, 0.0, 0.0, 1.0)));
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
