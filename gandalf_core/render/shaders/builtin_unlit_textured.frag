#version 330 core
// Built-in material gandalf.unlit with a texture: the material colour times the texture, no light.
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_texture;
out vec4 f_color;
void main() { f_color = material.color * texture(u_texture, v_uv); }
