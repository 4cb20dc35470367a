// The vertex stage of the lit shaders
// (phong, mirror, glass, emissive): world-space position and normal.
#include "frame.wgsl"
#include "instance.wgsl"

struct LitOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> LitOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    var out: LitOut;
    out.position = frame.projection * frame.view * world;
    out.world = world.xyz;
    out.normal = instance_normal(inst, normal);
    return out;
}
