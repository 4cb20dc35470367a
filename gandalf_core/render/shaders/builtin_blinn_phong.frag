#version 330 core
// Built-in material gandalf.blinn_phong, colour only: the scene's lights on the material colour.
#include "builtin_lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
uniform vec4 u_color;
uniform float u_specular;
uniform float u_shininess;
out vec4 f_color;
void main() {
    f_color = vec4(gandalf_builtin_lighting(v_world, v_normal, u_color.rgb, u_specular, u_shininess), u_color.a);
}
