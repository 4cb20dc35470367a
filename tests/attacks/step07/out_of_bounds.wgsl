// Attack: reads a million elements past the end of a local array.
fn face_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    return normalize(cross(p1 - p0, p2 - p0));
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32, period: f32) -> vec3<f32> {
    var table = array<f32, 4>(0.0, 0.25, 0.5, 1.0);
    let far = i32(abs(t) * 1000.0) + 1000000;
    return amount * (table[far] + table[-far]) * face_normal(p0, p1, p2);
}
