// Built-in material gandalf.unlit with a texture: the material colour times the texture, no light.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var color_texture: texture_2d<f32>;
@group(1) @binding(2) var color_sampler: sampler;
struct UnlitOut { @builtin(position) position: vec4<f32>, @location(0) uv: vec2<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(2) uv: vec2<f32>,
    inst: Instance) -> UnlitOut {
    return UnlitOut(
        frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0), uv);
}
@fragment fn fs_main(in: UnlitOut) -> @location(0) vec4<f32> {
    return material.color * textureSample(color_texture, color_sampler, in.uv);
}
