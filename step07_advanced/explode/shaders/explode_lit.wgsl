// The unexploded reference: the bunny from its vertex buffer, the
// same lighting as the exploding shader.
#include "explode_shading.wgsl"
#include "instance.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> SurfaceOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    var out: SurfaceOut;
    out.position = frame.projection * frame.view * world;
    out.world = world.xyz;
    out.normal = instance_normal(inst, normal);
    return out;
}
