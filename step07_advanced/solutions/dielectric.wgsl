// Exercise scatter_dielectric (step07 path tracer), WGSL: where a ray goes when it meets glass.
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
fn scatter_dielectric(dir: vec3<f32>, normal: vec3<f32>, ior: f32, u: f32) -> vec3<f32> {
    let d = normalize(dir);
    let entering = dot(d, normal) < 0.0;
    let n = select(-normal, normal, entering);
    let eta = select(ior, 1.0 / ior, entering);
    let cos_i = min(dot(-d, n), 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    var r0 = (1.0 - ior) / (1.0 + ior);
    r0 = r0 * r0;
    let reflectance = r0 + (1.0 - r0) * pow(1.0 - cos_i, 5.0);
    if (sin2_t > 1.0 || u < reflectance) {
        return normalize(d - 2.0 * dot(d, n) * n);
    }
    let t_perp = eta * (d + cos_i * n);
    let t_par = -sqrt(max(0.0, 1.0 - dot(t_perp, t_perp))) * n;
    return normalize(t_perp + t_par);
}
