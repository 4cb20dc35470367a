// Shadow mapping: how much of the shadow-casting light reaches a surface point (1 = all, 0 = none).
// The engine binds its shadow map to u_shadow_map
// (texture unit 15, not one of the material's textures).
#include "frame.glsl"
uniform sampler2DShadow u_shadow_map;

float shadow_factor(vec3 world_position, vec3 normal) {
    if (u_shadow.x < 0.5) {
        return 1.0;  // no light casts shadows
    }
    vec4 clip = u_light_view_projection * vec4(world_position, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    // OpenGL: NDC x, y, z in [-1, 1]; texture coordinates and stored
    // depth in [0, 1], row 0 at the bottom.
    vec3 coord = ndc * 0.5 + 0.5;
    if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0)))) {
        return 1.0;  // outside the light's box: nothing there was drawn into the map
    }
    // Slope-scaled bias: a surface tilted away from the light changes depth faster across a texel.
    vec3 l = normalize(u_light_position[int(u_shadow.w)].xyz);
    float cos_theta = clamp(dot(normalize(normal), l), 0.1, 1.0);
    float tan_theta = sqrt(1.0 - cos_theta * cos_theta) / cos_theta;
    float reference = coord.z - u_shadow.y * (1.5 + 2.0 * tan_theta);
    // 3x3 percentage-closer filtering: the fraction of nearby map texels the point is not behind.
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y) {
        for (int x = -1; x <= 1; ++x) {
            lit += textureLod(u_shadow_map,
                              vec3(coord.xy + vec2(x, y) * u_shadow.z, reference), 0.0);
        }
    }
    return lit / 9.0;
}
