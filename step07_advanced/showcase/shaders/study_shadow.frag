#version 330 core
// The shadow study: the engine's shadow lookup (shadow.glsl) with the percentage-closer filter's
// radius as a material parameter (material.pcf = r: (2r + 1)^2 taps). The output is the lit
// fraction itself (white = lit).
#include "shadow.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;

float study_shadow(vec3 world_position, vec3 normal, int r) {
    vec4 clip = u_light_view_projection * vec4(world_position, 1.0);
    vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0)))) {
        return 1.0;
    }
    vec3 l = normalize(u_light_position[int(u_shadow.w)].xyz);
    float cos_theta = clamp(dot(normalize(normal), l), 0.1, 1.0);
    float tan_theta = sqrt(1.0 - cos_theta * cos_theta) / cos_theta;
    float reference = coord.z - u_shadow.y * (1.5 + 2.0 * tan_theta);
    float lit = 0.0;
    for (int y = -r; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            lit += textureLod(u_shadow_map,
                              vec3(coord.xy + vec2(x, y) * u_shadow.z, reference), 0.0);
        }
    }
    float taps = float(2 * r + 1);
    return lit / (taps * taps);
}

void main() {
    float lit = u_shadow.x < 0.5 ? 1.0 : study_shadow(v_world, v_normal, int(material.pcf + 0.5));
    f_color = vec4(material.color.rgb * lit, 1.0);
}
