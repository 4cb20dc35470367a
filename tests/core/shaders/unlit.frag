#version 330 core
// Test shader: textured, tinted by the material colour.
in vec2 v_uv;
uniform vec4 u_color;
uniform sampler2D u_albedo;
out vec4 f_color;
void main() { f_color = u_color * texture(u_albedo, v_uv); }
