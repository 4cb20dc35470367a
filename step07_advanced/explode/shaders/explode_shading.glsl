// Two-sided Blinn-Phong with every light of the scene (the same sums as explode_shading.wgsl).
#include "frame.glsl"
#include "../../shaders/blinn_phong.glsl"

vec3 shade(vec3 p, vec3 normal, vec3 albedo, float specular, float shininess) {
    float nlen = length(normal);
    vec3 n = nlen > 1e-12 ? normal / nlen : vec3(0.0, 1.0, 0.0);
    vec3 d = u_camera_position.xyz - p;
    vec3 v = length(d) > 1e-12 ? normalize(d) : n;
    // Flying triangles show their inner sides: light a back face as if it faced the camera.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    return blinn_phong_lights(p, n, v, albedo, specular, shininess);
}
