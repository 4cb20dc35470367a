// The sky: one triangle covering the screen at the far plane; each
// pixel looks up its view direction.
#include "frame.wgsl"
#include "fullscreen.wgsl"
@group(1) @binding(0) var sky: texture_cube<f32>;
@group(1) @binding(1) var sky_sampler: sampler;

// Each corner carries its world view direction (xyz).
fn fullscreen_vertex(clip: vec2<f32>) -> FullscreenOut {
    return FullscreenOut(vec4<f32>(clip, frame.depth.y, 1.0), frame.clip_to_direction * vec4<f32>(clip, 1.0, 1.0));
}

@fragment
fn fs_main(in: FullscreenOut) -> @location(0) vec4<f32> {
    return vec4<f32>(textureSample(sky, sky_sampler, normalize(in.value.xyz)).rgb, 1.0);
}
