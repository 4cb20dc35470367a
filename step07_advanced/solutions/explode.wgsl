// Exercise explode_offset (reference): the displacement of an exploding triangle, in WGSL
// (used by the vertex-pulling shader).
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
    let e1 = p1 - p0;
    let e2 = p2 - p0;
    let m = max(abs(e1), abs(e2));
    let s = max(m.x, max(m.y, m.z));
    if (!(s > 0.0)) {
        return vec3<f32>(0.0);
    }
    let c = cross(e1 / s, e2 / s);
    let len = length(c);
    if (len <= 1e-12) {
        return vec3<f32>(0.0);
    }
    return c / len;
}

fn explode_offset(p0: vec3<f32>, p1: vec3<f32>, p2: vec3<f32>, t: f32, amount: f32,
    period: f32) -> vec3<f32> {
    let w = 0.5 - 0.5 * cos(6.283185307179586 * t / period);
    return amount * w * face_normal(p0, p1, p2);
}
