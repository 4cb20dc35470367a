// Blinn-Phong with every light of the scene, shared by step 07's lit techniques
// (explode, parallax); the same sums as blinn_phong.wgsl. p: the shaded point, n: the unit normal,
// v: the unit vector towards the eye (camera-relative positions, as the engine's frame and lights
// blocks hold them). Needs frame.glsl (the lights block) first.
vec3 blinn_phong_lights(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess) {
    vec3 color = u_ambient.rgb * albedo;
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec4 position = u_light_position[i];
        vec3 radiance = u_light_color[i].rgb;
        vec3 l = position.xyz;  // directional: a unit vector towards the light
        if (position.w > 0.5) {
            vec3 to_light = position.xyz - p;
            float distance = max(length(to_light), 1e-6);
            l = to_light / distance;
            float range = u_light_color[i].a;
            if (range > 0.0) {
                float x = distance / range;
                float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
                radiance *= window * window / max(distance * distance, 1e-4);
            }
        }
        float ndl = max(dot(n, l), 0.0);
        vec3 h = normalize(l + v);
        float spec = specular * pow(max(dot(n, h), 0.0), shininess) * ndl;
        color += (albedo * ndl + spec) * radiance;
    }
    return color;
}
