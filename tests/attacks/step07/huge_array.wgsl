// Attack: a local array of 200,000 floats filled on every call (the driver stalls compiling or running it).
fn face_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    return normalize(cross(p1 - p0, p2 - p0));
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32, period: f32) -> vec3<f32> {
    var big: array<f32, 200000>;
    for (var i = 0; i < 200000; i++) {
        big[i] = t * f32(i);
    }
    return amount * big[i32(abs(t) * 7919.0) % 200000] * face_normal(p0, p1, p2);
}
