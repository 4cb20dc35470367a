// Exercise scatter_dielectric (step07 path tracer), GLSL: where a ray goes when it meets glass.
// A wrong or black picture? `python -m step07_advanced.opengl --technique pathtracer --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// scatter_dielectric(dir, normal, ior, u) -> the new ray direction, unit length
//   dir:    the incoming direction, any non-zero length: normalise it first.
//   normal: the surface's unit OUTWARD normal (pointing out of the glass), whichever side
//           the ray comes from.
//   ior:    the glass's index of refraction (> 0; the outside is air, index 1).
//   u:      a uniform random number in [0, 1).
//   * Entering (dot(dir, normal) < 0): the ratio is eta = 1 / ior and the facing normal n = normal.
//     Leaving (dot(dir, normal) >= 0): eta = ior and n = -normal.
//   * cos_i = min(dot(-d, n), 1.0) with d the unit dir; Snell: sin_t^2 = eta^2 * (1 - cos_i^2).
//   * Total internal reflection: sin_t^2 > 1 -> reflect: d - 2 dot(d, n) n.
//   * Otherwise Schlick's reflectance R = r0 + (1 - r0) * (1 - cos_i)^5 with
//     r0 = ((1 - ior) / (1 + ior))^2; reflect when u < R, else refract:
//       t_perp = eta * (d + cos_i * n),  t_par = -sqrt(max(0, 1 - |t_perp|^2)) * n,
//       return t_perp + t_par.
//   * ior = 1 lets a ray straight through (r0 = 0). The result is unit length and never NaN.
// The stub absorbs every ray (returns a zero vector: the path tracer ends
// the path) until you write it.
vec3 scatter_dielectric(vec3 dir, vec3 normal, float ior, float u) {
    return vec3(0.0);
}
