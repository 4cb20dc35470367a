// Exercise explode_offset: the displacement of an exploding triangle,
// in WGSL (used by the vertex-pulling shader). Both functions return
// zero (no explosion) until you write them.
// A wrong or black picture? `python -m step07_advanced.webgpu --technique explode --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// face_normal(p0, p1, p2): the unit normal of the triangle by the right-hand rule on its winding,
//     n = normalize(cross(p1 - p0, p2 - p0))
//     (counter-clockwise seen from the front -> n points to the viewer;
//     a clockwise triangle gets -n).
//   * Divide both edges by their largest absolute component before the cross product, so a huge
//     (1e30) triangle does not overflow to inf and a tiny (1e-30) one does not underflow to zero.
//   * A zero-area triangle (coincident or collinear corners: the scaled cross product is shorter
//     than 1e-12) has no normal: return vec3(0.0). Never NaN.
// explode_offset(p0, p1, p2, t, amount, period): the world-space displacement of the whole face at
//     time t (s), offset = amount * (1 - cos(2*pi * t / period)) / 2 * face_normal(p0, p1, p2)
//   (radians; 0 at t = 0 and every whole period, amount * n at half a period, periodic and even in
//   t; amount >= 0 and period > 0 are checked on the CPU.)
fn face_normal(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(0.0);
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32,
    period: f32) -> vec3<f32> {
    return vec3<f32>(0.0);
}
