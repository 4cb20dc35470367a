// Built-in material gandalf.blinn_phong with a texture: the scene's
// lights on the colour times the texture.
#include "lit_varyings.wgsl"
#include "builtin_lighting.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var color_texture: texture_2d<f32>;
@group(1) @binding(2) var color_sampler: sampler;
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
                   @location(2) uv: vec2<f32>, inst: Instance) -> LitOut {
    return lit_vertex(inst, position, normal, uv);
}
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let albedo = material.color * textureSample(color_texture, color_sampler, in.uv);
    let lit = gandalf_builtin_lighting(in.world, in.normal, albedo.rgb, material.specular,
        material.shininess);
    return vec4<f32>(lit, albedo.a);
}
