// Test shader: Lambert lighting from the lights block.
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
    let n = normalize(in.normal);
    var c = lights.ambient.rgb * material.color.rgb;
    for (var i = 0; i < lights.count.x; i++) {
        c += material.color.rgb * lights.color[i].rgb
            * max(dot(n, normalize(lights.position[i].xyz)), 0.0);
    }
    return vec4<f32>(c, 1.0);
}
