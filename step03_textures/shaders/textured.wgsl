// Step 03: the material colour times one texture, sampled at the interpolated UV.
#include "frame.wgsl"
#include "instance.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo: texture_2d<f32>;      // the material's first texture ...
@group(1) @binding(2) var albedo_sampler: sampler;      // ... and, separately, how to sample it

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(2) uv: vec2<f32>,
    inst: Instance) -> VertexOut {
    var out: VertexOut;
    out.uv = uv;  // interpolated (perspective-correct) across the triangle
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    // An sRGB texture is decoded to linear light by the sampler, before filtering.
    return material.color * textureSample(albedo, albedo_sampler, in.uv);
}
