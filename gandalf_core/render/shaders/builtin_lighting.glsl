// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the Lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "light_sample.glsl"

vec3 gandalf_builtin_lighting(vec3 p, vec3 normal, vec3 albedo, float specular, float shininess) {
    vec3 n = safe_normalize(normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - p, n);
    vec3 total = u_ambient.rgb * albedo;
    int count = min(u_light_count.x, MAX_LIGHTS);
    for (int i = 0; i < count; ++i) {
        vec3 l, radiance;
        light_at(i, p, n, l, radiance);
        float diffuse = max(dot(n, l), 0.0);
        vec3 h = safe_normalize(l + v, n);
        float highlight = shininess > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 1.0;
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
