// Normal-shaded and textured (the house walls): texture times colour, lit like shaded.wgsl.
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;
struct VOut {
    @builtin(position) position: vec4<f32>,
    @location(0) normal: vec3<f32>,
    @location(1) uv: vec2<f32>,
};
@vertex fn vs_main(
    @location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) uv: vec2<f32>,
    inst: Instance,
) -> VOut {
    var out: VOut;
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    out.normal = instance_normal(inst, normal);
    out.uv = uv;
    return out;
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    let light = normalize(vec3<f32>(0.4, 0.8, 0.6));
    let lambert = max(dot(normalize(in.normal), light), 0.0);
    let albedo = material.color * textureSample(albedo, albedo_sampler, in.uv);
    return vec4<f32>(albedo.rgb * (0.3 + 0.7 * lambert), albedo.a);
}
