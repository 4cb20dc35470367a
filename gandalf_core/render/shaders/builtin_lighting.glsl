// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the Lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "light_sample.glsl"

vec3 gandalf_builtin_lighting(vec3 p, vec3 normal, vec3 albedo, float specular, float shininess) {
    float n_length = length(normal);
    vec3 n = n_length > 1e-12 ? normal / n_length : vec3(0.0, 1.0, 0.0);
    vec3 to_eye = u_camera_position.xyz - p;
    float eye_distance = length(to_eye);
    vec3 v = eye_distance > 1e-12 ? to_eye / eye_distance : n;
    vec3 total = u_ambient.rgb * albedo;
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec3 l, radiance;
        light_at(i, p, n, l, radiance);
        float diffuse = max(dot(n, l), 0.0);
        vec3 h = l + v;
        float h_length = length(h);
        h = h_length > 1e-6 ? h / h_length : n;
        float highlight = shininess > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 1.0;
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
