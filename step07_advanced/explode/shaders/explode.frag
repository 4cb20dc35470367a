#version 330 core
// Stage 3 of 3 (and the fragment stage of the unexploded reference): two-sided Blinn-Phong.
#include "explode_shading.glsl"
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_color;
uniform float u_specular;
uniform float u_shininess;
out vec4 f_color;
void main() {
    f_color = vec4(shade(v_world, v_normal, u_color.rgb, u_specular, u_shininess), 1.0);
}
