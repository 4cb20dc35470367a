// Test shader: textured, tinted by the material colour.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;
struct VOut { @builtin(position) position: vec4<f32>, @location(0) uv: vec2<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(2) uv: vec2<f32>,
    inst: Instance) -> VOut {
    var out: VOut;
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    out.uv = uv;
    return out;
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    return material.color * textureSample(albedo, albedo_sampler, in.uv);
}
