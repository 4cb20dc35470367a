// Normal-shaded: one colour, lit by a fixed world-space light:
// ambient 0.3 plus Lambert 0.7 (linear light).
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
struct VOut { @builtin(position) position: vec4<f32>, @location(0) normal: vec3<f32> };
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> VOut {
    var out: VOut;
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    out.normal = instance_normal(inst, normal);  // correct under any scale
    return out;
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    let light = normalize(vec3<f32>(0.4, 0.8, 0.6));
    let lambert = max(dot(normalize(in.normal), light), 0.0);
    return vec4<f32>(material.color.rgb * (0.3 + 0.7 * lambert), material.color.a);
}
