// Test shader piece: the vertex stage of the lit test shaders (lit.wgsl, the shadow test's): clip position,
// world position and world normal.
#include "frame.wgsl"
#include "instance.wgsl"
struct VOut { @builtin(position) position: vec4<f32>, @location(0) world: vec3<f32>, @location(1) normal: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, inst: Instance) -> VOut {
    var out: VOut;
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    out.position = frame.projection * frame.view * world;
    out.world = world.xyz;
    out.normal = instance_normal(inst, normal);
    return out;
}
