// Shadow mapping: how much of the shadow-casting light reaches a surface point (1 = all, 0 = none).
// The engine binds its shadow map here (a 1x1 stand-in when no light casts shadows).
#include "frame.wgsl"
@group(0) @binding(2) var shadow_map: texture_depth_2d;
@group(0) @binding(3) var shadow_sampler: sampler_comparison;

fn shadow_factor(world_position: vec3<f32>, normal: vec3<f32>) -> f32 {
    if (lights.shadow.x < 0.5) {
        return 1.0;  // no light casts shadows
    }
    let clip = lights.light_view_projection * vec4<f32>(world_position, 1.0);
    let ndc = clip.xyz / clip.w;
    // WebGPU: NDC depth is already in [0, 1]; texture rows run top-down while NDC y runs up.
    let coord = vec3<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5, ndc.z);
    if (any(coord < vec3<f32>(0.0)) || any(coord > vec3<f32>(1.0))) {
        return 1.0;  // outside the light's box: nothing there was drawn into the map
    }
    // Slope-scaled bias: a surface tilted away from the light changes depth faster across a texel.
    let l = normalize(lights.position[i32(lights.shadow.w)].xyz);
    let cos_theta = clamp(dot(normalize(normal), l), 0.1, 1.0);
    let tan_theta = sqrt(1.0 - cos_theta * cos_theta) / cos_theta;
    let reference = coord.z - lights.shadow.y * (1.5 + 2.0 * tan_theta);
    // 3x3 percentage-closer filtering: the fraction of nearby map texels the point is not behind.
    var lit = 0.0;
    for (var y = -1; y <= 1; y++) {
        for (var x = -1; x <= 1; x++) {
            let uv = coord.xy + vec2<f32>(f32(x), f32(y)) * lights.shadow.z;
            lit += textureSampleCompareLevel(shadow_map, shadow_sampler, uv, reference);
        }
    }
    return lit / 9.0;
}
