// Attack: explode_offset never returns (an even counter stepped by 2 never reaches 1).
fn face_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    return normalize(cross(p1 - p0, p2 - p0));
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32, period: f32) -> vec3<f32> {
    var i = u32(abs(t)) * 2u;
    loop {
        if (i == 1u) {
            break;
        }
        i = i + 2u;
    }
    return vec3<f32>(f32(i)) * amount;
}
