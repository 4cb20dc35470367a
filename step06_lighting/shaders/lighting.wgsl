// All lights of the lights block at one surface point: ambient + the sum
// of blinn_phong() over the lights. blinn_phong() comes from
// shading.wgsl, which the variant file finds in exercises/ or solutions/.
#include "frame.wgsl"
#include "shading.wgsl"

// --8<-- [start:lights]
struct LightSample {
    l: vec3<f32>,         // unit direction towards the light
    radiance: vec3<f32>,  // colour × intensity × distance falloff
};

// A point light exactly at p lights it head-on (l = n) instead of normalising a zero vector.
fn light_at(i: i32, p: vec3<f32>, n: vec3<f32>) -> LightSample {
    let position = lights.position[i];
    let color = lights.color[i];
    if (position.w < 0.5) {
        return LightSample(position.xyz, color.rgb);  // directional: already a unit
                                                      // vector towards the light
    }
    let d = position.xyz - p;
    let distance = length(d);
    let l = select(n, d / max(distance, 1e-6), distance > 1e-6);
    var radiance = color.rgb;
    if (color.a > 0.0) {
        // Windowed inverse square (glTF's punctual lights): fades to exactly zero at the range.
        let x = distance / color.a;
        let window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        radiance *= window * window / max(distance * distance, 1e-4);
    }
    return LightSample(l, radiance);
}

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
