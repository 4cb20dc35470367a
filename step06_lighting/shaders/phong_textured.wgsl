// Blinn-Phong whose albedo is the material colour times its texture.
#include "lit_varyings.wgsl"
#include "lighting.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo_texture: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
           @location(2) uv: vec2<f32>, inst: Instance) -> LitOut {
    return lit_vertex(inst, position, normal, uv);  // the engine's lit_varyings.wgsl
}

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    let albedo = material.color.rgb * textureSample(albedo_texture, albedo_sampler, in.uv).rgb;
    return vec4<f32>(shade(in.world, n, v, albedo, material.specular, material.shininess), 1.0);
}
