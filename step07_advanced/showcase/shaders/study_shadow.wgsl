// The shadow study: the engine's shadow lookup (shadow.wgsl) with the
// percentage-closer filter's radius as a material parameter
// (pcf = r: (2r + 1)^2 taps). The output is the lit fraction itself (white = lit).
#include "lit_vertex.wgsl"
#include "shadow.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader

fn study_shadow(world_position: vec3<f32>, normal: vec3<f32>, r: i32) -> f32 {
    let clip = lights.light_view_projection * vec4<f32>(world_position, 1.0);
    let ndc = clip.xyz / clip.w;
    let coord = vec3<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5, ndc.z);
    if (any(coord < vec3<f32>(0.0)) || any(coord > vec3<f32>(1.0))) {
        return 1.0;
    }
    let l = normalize(lights.position[i32(lights.shadow.w)].xyz);
    let cos_theta = clamp(dot(normalize(normal), l), 0.1, 1.0);
    let tan_theta = sqrt(1.0 - cos_theta * cos_theta) / cos_theta;
    let reference = coord.z - lights.shadow.y * (1.5 + 2.0 * tan_theta);
    var lit = 0.0;
    for (var y = -r; y <= r; y++) {
        for (var x = -r; x <= r; x++) {
            let uv = coord.xy + vec2<f32>(f32(x), f32(y)) * lights.shadow.z;
            lit += textureSampleCompareLevel(shadow_map, shadow_sampler, uv, reference);
        }
    }
    let taps = f32(2 * r + 1);
    return lit / (taps * taps);
}

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    var lit = 1.0;
    if (lights.shadow.x >= 0.5) {
        lit = study_shadow(in.world, in.normal, i32(material.pcf + 0.5));
    }
    return vec4<f32>(material.color.rgb * lit, 1.0);
}
