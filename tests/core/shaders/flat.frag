#version 330 core
// Test shader: the material colour.
uniform vec4 u_color;
out vec4 f_color;
void main() { f_color = u_color; }
