// Image-based light with the split sum (Karis 2013), from three precomputed maps (see ibl.py):
//   diffuse  = diffuse_albedo(base, metallic, F) · irradiance(n)   (irradiance map holds E(n)/π)
//   specular = prefiltered(r, roughness) · (F0 · A + B)             (A, B from the BRDF table)
// with F = fresnel_schlick_roughness(n·v, F0, roughness) and
// F0 = base_reflectance(base, metallic): the student's functions from
// brdf.glsl. Level k of the prefiltered cube holds roughness k / (levels - 1).
// --8<-- [start:ibl]
vec3 ibl_light(samplerCube irradiance, samplerCube prefiltered, sampler2D brdf_lut, float levels,
               vec3 n, vec3 v, vec3 base, float metallic, float roughness) {
    float n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
    vec3 f0 = base_reflectance(base, metallic);
    vec3 f = fresnel_schlick_roughness(n_dot_v, f0, roughness);
    vec3 diffuse = diffuse_albedo(base, metallic, f) * textureLod(irradiance, n, 0.0).rgb;
    vec3 radiance = textureLod(prefiltered, reflect(-v, n), roughness * (levels - 1.0)).rgb;
    vec2 ab = textureLod(brdf_lut, vec2(n_dot_v, roughness), 0.0).rg;
    return diffuse + radiance * (f0 * ab.x + ab.y);
}
// --8<-- [end:ibl]
