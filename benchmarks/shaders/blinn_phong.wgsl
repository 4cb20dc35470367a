// pyGANDALF comparison: Blinn-Phong with the engine's lights
// (positions relative to the camera, at the origin).
#include "frame.wgsl"
#include "instance.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
struct VOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
};
@vertex fn vs_main(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>,
    inst: Instance) -> VOut {
    var out: VOut;
    let world = instance_model(inst) * vec4<f32>(position, 1.0);
    out.position = world.xyz;
    out.normal = instance_normal(inst, normal);
    out.clip = frame.projection * frame.view * world;
    return out;
}
@fragment fn fs_main(in: VOut) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let v = normalize(-in.position);
    var c = lights.ambient.rgb * material.color.rgb;
    for (var i = 0; i < lights.count.x; i++) {
        let p = lights.position[i];
        var l = normalize(p.xyz);
        if (p.w != 0.0) { l = normalize(p.xyz - in.position); }
        let h = normalize(l + v);
        let d = max(dot(n, l), 0.0);
        var s = 0.0;
        if (d > 0.0) { s = pow(max(dot(n, h), 0.0), 32.0); }
        c += lights.color[i].rgb * (material.color.rgb * d + vec3<f32>(0.3) * s);
    }
    return vec4<f32>(c, material.color.a);
}
