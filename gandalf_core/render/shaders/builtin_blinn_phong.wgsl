// Built-in material gandalf.blinn_phong, colour only: the scene's lights on the material colour.
#include "instance.wgsl"
#include "builtin_lighting.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
struct LitOut { @builtin(position) position: vec4<f32>, @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> LitOut {
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    return LitOut(frame.projection * frame.view * world, world.xyz, instance_normal(inst, normal));
}
@fragment fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let lit = gandalf_builtin_lighting(in.world, in.normal, material.color.rgb, material.specular,
        material.shininess);
    return vec4<f32>(lit, material.color.a);
}
