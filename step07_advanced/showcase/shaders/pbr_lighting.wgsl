// Metallic-roughness shading with every light of the scene, plus an environment term from a sky
// cube map. ggx_specular(), fresnel_schlick(), base_reflectance() and diffuse_albedo() come from
// brdf.wgsl (exercises/ or solutions/); shadow_factor() from the engine's shadow.wgsl.
#include "light_sample.wgsl"  // light_at(): the engine's, as in step 06
#include "shadow.wgsl"
#include "brdf.wgsl"

const PI: f32 = 3.14159265358979;
// Perceptual roughness below this makes the GGX lobe narrower than a pixel
// (and D overflow float16 GPUs).
const MIN_ROUGHNESS: f32 = 0.045;

// A unit vector from a possibly unnormalised (or zero) one: interpolated normals can cancel out.
fn safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len = length(v);
    return select(fallback, v / max(len, 1e-12), len > 1e-12);
}

// Direct light: sum over the lights of (diffuse_albedo/π + specular BRDF) · radiance · n·l, plus
// the lights block's ambient. diffuse_albedo = base (1 - metallic)(1 - F): what is reflected
// specularly is not scattered. `shadow` is the part of the shadow-casting light that reaches p
// (shadow_factor(); 1 without shadows).
// --8<-- [start:direct]
fn pbr_direct(p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, base: vec3<f32>, metallic: f32,
              roughness: f32, shadow: f32) -> vec3<f32> {
    let r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    let f0 = base_reflectance(base, metallic);
    let diffuse = base * (1.0 - metallic);
    var color = lights.ambient.rgb * (diffuse + f0);
    let count = min(lights.count.x, i32(MAX_LIGHTS));
    for (var i = 0; i < count; i++) {
        let s = light_at(i, p, n);
        let n_dot_l = dot(n, s.l);
        if (n_dot_l <= 0.0) {
            continue;
        }
        let radiance = select(s.radiance, s.radiance * shadow, i == i32(lights.shadow.w));
        let h = safe_normalize(s.l + v, n);
        let diffuse_part = diffuse_albedo(base, metallic, fresnel_schlick(max(dot(h, v), 0.0), f0));
        color += (diffuse_part / PI + ggx_specular(n, v, s.l, r, f0)) * radiance * n_dot_l;
    }
    return color;
}
// --8<-- [end:direct]

// Image-based light from a (mip-mapped) cube map: blurrier mips stand in for
// rougher lobes (split sum with Karis' analytic fit of the pre-integrated
// BRDF); the diffuse part reads a nearly fully blurred level.
fn pbr_environment(env: texture_cube<f32>, env_sampler: sampler, n: vec3<f32>, v: vec3<f32>,
                   base: vec3<f32>, metallic: f32, roughness: f32) -> vec3<f32> {
    let r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    let f0 = base_reflectance(base, metallic);
    let n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
    let max_lod = log2(f32(textureDimensions(env).x));
    let specular_light = textureSampleLevel(env, env_sampler, reflect(-v, n), r * max_lod).rgb;
    let diffuse_light = textureSampleLevel(env, env_sampler, n, max_lod - 1.5).rgb;
    let c = r * vec4<f32>(-1.0, -0.0275, -0.572, 0.022) + vec4<f32>(1.0, 0.0425, 1.04, -0.04);
    let a004 = min(c.x * c.x, exp2(-9.28 * n_dot_v)) * c.x + c.y;
    let ab = vec2<f32>(-1.04, 1.04) * a004 + c.zw;
    return base * (1.0 - metallic) * diffuse_light + specular_light * (f0 * ab.x + ab.y);
}
