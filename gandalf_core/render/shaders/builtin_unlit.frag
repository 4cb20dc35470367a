#version 330 core
// Built-in material gandalf.unlit, colour only: the material colour (linear), no light.
uniform vec4 u_color;
out vec4 f_color;
void main() { f_color = u_color; }
