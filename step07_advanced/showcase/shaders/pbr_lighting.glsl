// Metallic-roughness shading with every light of the scene, plus an environment term from a sky
// cube map. ggx_specular(), fresnel_schlick(), base_reflectance() and diffuse_albedo() come from
// brdf.glsl (exercises/ or solutions/); shadow_factor() from the engine's shadow.glsl.
#include "light_sample.glsl"  // light_at(): the engine's, as in step 06
#include "shadow.glsl"
#include "brdf.glsl"

const float PI = 3.14159265358979;
// Perceptual roughness below this makes the GGX lobe narrower than a pixel
// (and D overflow float16 GPUs).
const float MIN_ROUGHNESS = 0.045;

// A unit vector from a possibly unnormalised (or zero) one: interpolated normals can cancel out.
vec3 safe_normalize(vec3 v, vec3 fallback) {
    float len = length(v);
    return len > 1e-12 ? v / len : fallback;
}

// Direct light: sum over the lights of (diffuse_albedo/π + specular BRDF) · radiance · n·l, plus
// the lights block's ambient. diffuse_albedo = base (1 - metallic)(1 - F): what is reflected
// specularly is not scattered. `shadow` is the part of the shadow-casting light that reaches p
// (shadow_factor(); 1 without shadows).
// --8<-- [start:direct]
vec3 pbr_direct(vec3 p, vec3 n, vec3 v, vec3 base, float metallic, float roughness, float shadow) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    vec3 f0 = base_reflectance(base, metallic);
    vec3 diffuse = base * (1.0 - metallic);
    vec3 color = u_ambient.rgb * (diffuse + f0);
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec3 l, radiance;
        light_at(i, p, n, l, radiance);
        if (i == int(u_shadow.w)) {
            radiance *= shadow;
        }
        float n_dot_l = dot(n, l);
        if (n_dot_l <= 0.0) {
            continue;
        }
        vec3 h = safe_normalize(l + v, n);
        vec3 diffuse_part = diffuse_albedo(base, metallic,
            fresnel_schlick(max(dot(h, v), 0.0), f0));
        color += (diffuse_part / PI + ggx_specular(n, v, l, r, f0)) * radiance * n_dot_l;
    }
    return color;
}
// --8<-- [end:direct]

// Image-based light from a (mip-mapped) cube map: blurrier mips stand in for
// rougher lobes (split sum with Karis' analytic fit of the pre-integrated
// BRDF); the diffuse part reads a nearly fully blurred level.
vec3 pbr_environment(samplerCube env, vec3 n, vec3 v, vec3 base, float metallic, float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0);
    vec3 f0 = base_reflectance(base, metallic);
    float n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
    float max_lod = log2(float(textureSize(env, 0).x));
    vec3 specular_light = textureLod(env, reflect(-v, n), r * max_lod).rgb;
    vec3 diffuse_light = textureLod(env, n, max_lod - 1.5).rgb;
    vec4 c = r * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float a004 = min(c.x * c.x, exp2(-9.28 * n_dot_v)) * c.x + c.y;
    vec2 ab = vec2(-1.04, 1.04) * a004 + c.zw;
    return base * (1.0 - metallic) * diffuse_light + specular_light * (f0 * ab.x + ab.y);
}
