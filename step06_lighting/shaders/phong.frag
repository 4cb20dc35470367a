#version 330 core
// Blinn-Phong with every light of the scene and a per-material colour.
#include "lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_color;
uniform float u_specular;
uniform float u_shininess;
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    f_color = vec4(shade(v_world, n, v, u_color.rgb, u_specular, u_shininess), 1.0);
}
