// Attack: an expression nested a hundred thousand brackets deep (naga's parser recurses until the stack overflows:
// a segmentation fault of the process that compiles it).
fn face_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    return normalize(cross(p1 - p0, p2 - p0));
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32, period: f32) -> vec3<f32> {
    let w = @@NESTED@@;
    return amount * w * face_normal(p0, p1, p2);
}
