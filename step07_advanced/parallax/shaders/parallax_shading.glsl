// Blinn-Phong with every light of the scene: step 07's shared sums
// (the same as parallax_shading.wgsl).
#include "../../shaders/blinn_phong.glsl"

vec3 shade(vec3 p, vec3 n, vec3 v, vec3 albedo, float specular, float shininess) {
    return blinn_phong_lights(p, n, v, albedo, specular, shininess);
}
