#version 330 core
// The textured glTF model: metallic-roughness, normal, occlusion and emissive
// maps, lit by the scene's lights (pbr_direct, from the showcase) and by
// image-based light (ibl.glsl). Samplers follow the material's texture order
// (gandalf_core.resources.gltf): five maps, then the three IBL textures.
#include "pbr_lighting.glsl"
#include "normal_map.glsl"
#include "ibl.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_base_color_map;
uniform sampler2D u_metallic_roughness_map;
uniform sampler2D u_normal_map;
uniform sampler2D u_occlusion_map;
uniform sampler2D u_emissive_map;
uniform samplerCube u_irradiance;
uniform samplerCube u_prefiltered;
uniform sampler2D u_brdf_lut;
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    // --8<-- [start:maps]
    // sRGB texture: decoded to linear
    vec3 base = material.color.rgb * texture(u_base_color_map, v_uv).rgb;
    // linear: G = roughness, B = metallic
    vec4 mr = texture(u_metallic_roughness_map, v_uv);
    float metallic = clamp(material.metallic * mr.b, 0.0, 1.0);
    float roughness = clamp(material.roughness * mr.g, 0.0, 1.0);
    vec3 m = texture(u_normal_map, v_uv).rgb * 2.0 - 1.0;
    m.xy *= material.normal_scale;
    vec3 shading = perturb_normal(n, v_tangent, m * 0.5 + 0.5);
    float ao = 1.0 + material.occlusion_strength * (texture(u_occlusion_map, v_uv).r - 1.0);
    vec3 emitted = material.emissive.rgb * texture(u_emissive_map, v_uv).rgb;
    // --8<-- [end:maps]
    vec3 color = pbr_direct(v_world, shading, v, base, metallic, roughness,
        shadow_factor(v_world, n));
    color += material.env_strength * ao * ibl_light(u_irradiance, u_prefiltered, u_brdf_lut,
        material.prefiltered_levels, shading, v, base, metallic, roughness);
    f_color = vec4(color + emitted, 1.0);
}
