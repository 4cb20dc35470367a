// Reference solution: decoding a tangent-space normal map with the TBN frame, in WGSL.

fn perturb_normal(n: vec3<f32>, tangent: vec4<f32>, map_rgb: vec3<f32>) -> vec3<f32> {
    let m = map_rgb * 2.0 - 1.0;
    // Gram-Schmidt: interpolation leaves the tangent slightly off the normal's plane.
    var t = tangent.xyz - n * dot(n, tangent.xyz);
    let t_length = length(t);
    if (t_length > 1e-6) {
        t = t / t_length;
    } else {
        // No usable tangent (zero, or parallel to n): any perpendicular keeps the result finite.
        let axis = select(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(1.0, 0.0, 0.0), abs(n.x) < 0.9);
        t = normalize(axis - n * dot(n, axis));
    }
    let b = cross(n, t) * select(1.0, -1.0, tangent.w < 0.0);
    let r = t * m.x + b * m.y + n * m.z;
    let r_length = length(r);
    return select(n, r / max(r_length, 1e-6), r_length > 1e-6);
}
