// All lights of the lights block at one surface point: ambient + the sum
// of blinn_phong() over the lights. blinn_phong() comes from
// shading.wgsl, which the variant file finds in exercises/ or solutions/.
#include "light_sample.wgsl"  // light_at(): the engine's, one light seen from p
#include "shading.wgsl"

// --8<-- [start:lights]
fn shade(p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, albedo: vec3<f32>, specular: f32,
    shininess: f32) -> vec3<f32> {
    var color = lights.ambient.rgb * albedo;
    let count = min(lights.count.x, i32(MAX_LIGHTS));
    for (var i = 0; i < count; i++) {
        let s = light_at(i, p, n);
        color += blinn_phong(n, s.l, v, s.radiance, albedo, specular, shininess);
    }
    return color;
}
// --8<-- [end:lights]

// A unit vector from a possibly unnormalised (or zero) one: interpolated normals can cancel out.
fn safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len = length(v);
    return select(fallback, v / max(len, 1e-12), len > 1e-12);
}
