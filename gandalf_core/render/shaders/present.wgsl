// Copies the offscreen frame to the window: one triangle that covers the screen.
#include "fullscreen.wgsl"
@group(0) @binding(0) var frame: texture_2d<f32>;
@group(0) @binding(1) var frame_sampler: sampler;

// Each corner carries its texture coordinates (xy: the frame's top row at v = 0, drawn at the top).
fn fullscreen_vertex(clip: vec2<f32>) -> FullscreenOut {
    return FullscreenOut(vec4<f32>(clip.x, -clip.y, 0.0, 1.0), vec4<f32>(clip * 0.5 + 0.5, 0.0, 0.0));
}

@fragment
fn fs_main(in: FullscreenOut) -> @location(0) vec4<f32> {
    return textureSample(frame, frame_sampler, in.value.xy);
}
