// The lit vertex stage's output, shared by the engine's lit materials and any lit shader that includes it:
// clip position, world position, world normal and texture coordinate, filled in by lit_vertex().
#include "frame.wgsl"
#include "instance.wgsl"
struct LitOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};
fn lit_vertex(inst: Instance, position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> LitOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    return LitOut(frame.projection * frame.view * world, world.xyz, instance_normal(inst, normal), uv);
}
