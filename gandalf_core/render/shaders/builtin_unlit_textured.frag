#version 330 core
// Built-in material gandalf.unlit with a texture: the material colour times the texture, no light.
in vec2 v_uv;
uniform vec4 u_color;
uniform sampler2D u_texture;
out vec4 f_color;
void main() { f_color = u_color * texture(u_texture, v_uv); }
