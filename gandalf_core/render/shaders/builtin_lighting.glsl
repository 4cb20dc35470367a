// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the Lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "frame.glsl"

// A point light's falloff: the inverse square, windowed to reach zero at the light's range (range <= 0: none).
float gandalf_range_falloff(float distance, float range) {
    if (range <= 0.0) {
        return 1.0;
    }
    float x = distance / range;
    float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
    return window * window / max(distance * distance, 1e-4);
}

vec3 gandalf_builtin_lighting(vec3 p, vec3 normal, vec3 albedo, float specular, float shininess) {
    float n_length = length(normal);
    vec3 n = n_length > 1e-12 ? normal / n_length : vec3(0.0, 1.0, 0.0);
    vec3 to_eye = u_camera_position.xyz - p;
    float eye_distance = length(to_eye);
    vec3 v = eye_distance > 1e-12 ? to_eye / eye_distance : n;
    vec3 total = u_ambient.rgb * albedo;
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec4 position = u_light_position[i];
        vec3 radiance = u_light_color[i].rgb;
        vec3 l = position.xyz;  // directional (w = 0): a unit vector towards the light
        if (position.w > 0.5) {
            vec3 d = position.xyz - p;
            float distance = length(d);
            l = distance > 1e-6 ? d / distance : n;
            radiance *= gandalf_range_falloff(distance, u_light_color[i].a);
        }
        float diffuse = max(dot(n, l), 0.0);
        vec3 h = l + v;
        float h_length = length(h);
        h = h_length > 1e-6 ? h / h_length : n;
        float highlight = shininess > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 1.0;
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
