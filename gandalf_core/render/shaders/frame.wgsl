// Per-frame uniforms (binding 0) and lights (binding 1): the same bytes as frame.glsl. The structs are written from
// their one declaration, FRAME_LAYOUT and LIGHTS_LAYOUT in gandalf_core/resources/blocks.py, and packed in
// gandalf_core/render/frame.py and gandalf_core/systems/light_system.py.
// Time (see frame.py): time.x seconds wrapped to 1024 (fract(time.x * f) smooth for whole 1024 f), time.z its
// wraps, time.y the frame's step, time.w seconds wrapped to 163 turns of 2*pi (sin(k * time.w) smooth for whole k).
#include "blocks.wgsl"

// A world position made relative to the camera, as every position the engine hands the GPU is
// (instance rows, lights): for shaders that build absolute world positions themselves
// (a terrain at the world's origin).
fn world_to_relative(p: vec3<f32>) -> vec3<f32> {
    return p - frame.origin_high.xyz - frame.origin_low.xyz;
}
