// The textured glTF model: metallic-roughness, normal, occlusion and emissive
// maps, lit by the scene's lights (pbr_direct, from the showcase) and by
// image-based light (ibl.wgsl). Bindings follow the material's texture order
// (gandalf_core.resources.gltf): five maps, then the three IBL textures.
#include "surface_vertex.wgsl"
#include "pbr_lighting.wgsl"
#include "normal_map.wgsl"
#include "ibl.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var base_color_map: texture_2d<f32>;
@group(1) @binding(2) var base_color_sampler: sampler;
@group(1) @binding(3) var metallic_roughness_map: texture_2d<f32>;
@group(1) @binding(4) var metallic_roughness_sampler: sampler;
@group(1) @binding(5) var normal_map: texture_2d<f32>;
@group(1) @binding(6) var normal_sampler: sampler;
@group(1) @binding(7) var occlusion_map: texture_2d<f32>;
@group(1) @binding(8) var occlusion_sampler: sampler;
@group(1) @binding(9) var emissive_map: texture_2d<f32>;
@group(1) @binding(10) var emissive_sampler: sampler;
@group(1) @binding(11) var irradiance: texture_cube<f32>;
@group(1) @binding(12) var irradiance_sampler: sampler;
@group(1) @binding(13) var prefiltered: texture_cube<f32>;
@group(1) @binding(14) var prefiltered_sampler: sampler;
@group(1) @binding(15) var brdf_lut: texture_2d<f32>;
@group(1) @binding(16) var lut_sampler: sampler;

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    // --8<-- [start:maps]
    // sRGB
    let base = material.color.rgb * textureSample(base_color_map, base_color_sampler, in.uv).rgb;
    // G rough, B metal
    let mr = textureSample(metallic_roughness_map, metallic_roughness_sampler, in.uv);
    let metallic = clamp(material.metallic * mr.b, 0.0, 1.0);
    let roughness = clamp(material.roughness * mr.g, 0.0, 1.0);
    var m = textureSample(normal_map, normal_sampler, in.uv).rgb * 2.0 - 1.0;
    m = vec3<f32>(m.xy * material.normal_scale, m.z);
    let shading = perturb_normal(n, in.tangent, m * 0.5 + 0.5);
    let ao = 1.0 + material.occlusion_strength
        * (textureSample(occlusion_map, occlusion_sampler, in.uv).r - 1.0);
    let emitted = material.emissive.rgb * textureSample(emissive_map, emissive_sampler, in.uv).rgb;
    // --8<-- [end:maps]
    let shadow = shadow_factor(in.world, n);
    var color = pbr_direct(in.world, shading, v, base, metallic, roughness, shadow);
    color += material.env_strength * ao * ibl_light(irradiance, irradiance_sampler,
        prefiltered, prefiltered_sampler, brdf_lut, lut_sampler, material.prefiltered_levels,
        shading, v, base, metallic, roughness);
    return vec4<f32>(color + emitted, 1.0);
}
