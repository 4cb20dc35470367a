// Benchmark shader: world-space normal per vertex, Lambert shading in the fragment stage
// (one fixed directional light plus ambient, tinted by the material colour, in linear light).
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
    let diffuse = max(dot(normalize(in.normal), normalize(vec3<f32>(0.3, 0.5, 1.0))), 0.0);
    return vec4<f32>(material.color.rgb * (0.15 + 0.85 * diffuse), material.color.a);
}
