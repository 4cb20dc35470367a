// The shadow pass: each opaque surface's depth as the shadow-casting light sees it (no colour).
#include "frame.wgsl"
#include "instance.wgsl"

@vertex
fn vs_main(@location(0) position: vec3<f32>, inst: Instance) -> @builtin(position) vec4<f32> {
    return lights.light_view_projection * instance_model(inst) * vec4<f32>(position, 1.0);
}

// Depth only: the rasteriser stores it, this stage adds nothing
// (the pipeline has no colour target).
@fragment
fn fs_main() {
}
