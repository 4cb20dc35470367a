// Exercise explode_offset: the displacement of an exploding triangle,
// in GLSL (used by the explode geometry shader). Both functions
// return zero (no explosion) until you write them.
// A wrong or black picture? `python -m step07_advanced.opengl --technique explode --student --editor`:
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
vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
    return vec3(0.0);
}

vec3 explode_offset(vec3 p0, vec3 p1, vec3 p2, float t, float amount, float period) {
    return vec3(0.0);
}
