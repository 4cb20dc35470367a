#version 330 core
// Built-in material gandalf.blinn_phong with a texture: the scene's lights on the colour times the texture.
#include "builtin_lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
uniform vec4 u_color;
uniform float u_specular;
uniform float u_shininess;
uniform sampler2D u_texture;
out vec4 f_color;
void main() {
    vec4 albedo = u_color * texture(u_texture, v_uv);
    f_color = vec4(gandalf_builtin_lighting(v_world, v_normal, albedo.rgb, u_specular, u_shininess), albedo.a);
}
