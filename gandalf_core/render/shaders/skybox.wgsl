// The sky: one triangle covering the screen at the far plane; each
// pixel looks up its view direction.
#include "frame.wgsl"
@group(1) @binding(0) var sky: texture_cube<f32>;
@group(1) @binding(1) var sky_sampler: sampler;

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) direction: vec3<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) index: u32) -> VertexOut {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    let clip = uv * 2.0 - 1.0;
    var out: VertexOut;
    out.direction = (frame.clip_to_direction * vec4<f32>(clip, 1.0, 1.0)).xyz;
    out.position = vec4<f32>(clip, frame.depth.y, 1.0);
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(textureSample(sky, sky_sampler, normalize(in.direction)).rgb, 1.0);
}
