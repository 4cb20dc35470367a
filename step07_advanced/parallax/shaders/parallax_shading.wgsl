// Blinn-Phong with every light of the scene: step 07's shared sums
// (the same as parallax_shading.glsl).
#include "../../shaders/blinn_phong.wgsl"

fn shade(p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, albedo: vec3<f32>, specular: f32,
    shininess: f32) -> vec3<f32> {
    return blinn_phong_lights(p, n, v, albedo, specular, shininess);
}
