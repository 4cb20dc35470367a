// Image-based light with the split sum (Karis 2013), from three precomputed maps (see ibl.py):
//   diffuse  = diffuse_albedo(base, metallic, F) · irradiance(n)   (irradiance map holds E(n)/π)
//   specular = prefiltered(r, roughness) · (F0 · A + B)             (A, B from the BRDF table)
// with F = fresnel_schlick_roughness(n·v, F0, roughness) and
// F0 = base_reflectance(base, metallic): the student's functions from
// brdf.wgsl. Level k of the prefiltered cube holds roughness k / (levels - 1).
// --8<-- [start:ibl]
fn ibl_light(irradiance: texture_cube<f32>, irradiance_sampler: sampler,
             prefiltered: texture_cube<f32>, prefiltered_sampler: sampler,
             brdf_lut: texture_2d<f32>, lut_sampler: sampler, levels: f32,
             n: vec3<f32>, v: vec3<f32>, base: vec3<f32>, metallic: f32,
             roughness: f32) -> vec3<f32> {
    let n_dot_v = clamp(dot(n, v), 1e-4, 1.0);
    let f0 = base_reflectance(base, metallic);
    let f = fresnel_schlick_roughness(n_dot_v, f0, roughness);
    let diffuse = diffuse_albedo(base, metallic, f)
        * textureSampleLevel(irradiance, irradiance_sampler, n, 0.0).rgb;
    let radiance = textureSampleLevel(prefiltered, prefiltered_sampler, reflect(-v, n),
        roughness * (levels - 1.0)).rgb;
    let ab = textureSampleLevel(brdf_lut, lut_sampler, vec2<f32>(n_dot_v, roughness), 0.0).rg;
    return diffuse + radiance * (f0 * ab.x + ab.y);
}
// --8<-- [end:ibl]
