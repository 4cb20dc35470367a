#version 330 core
// Blinn-Phong with every light of the scene and a per-material colour.
#include "lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    vec3 lit = shade(v_world, n, v, material.color.rgb, material.specular, material.shininess);
    f_color = vec4(lit, 1.0);
}
