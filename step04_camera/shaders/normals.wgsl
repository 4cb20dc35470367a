// Shows the world-space normal as a colour: a quick way to see the shape of a mesh without lights.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
struct VOut { @builtin(position) position: vec4<f32>, @location(0) normal: vec3<f32> };

@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> VOut {
    var out: VOut;
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    out.normal = instance_normal(inst, normal);
    return out;
}

@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    // Map each component from [-1, 1] to [0, 1].
    return material.color * vec4<f32>(normalize(in.normal) * 0.5 + 0.5, 1.0);
}
