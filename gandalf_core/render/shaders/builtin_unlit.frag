#version 330 core
// Built-in material gandalf.unlit, colour only: the material colour (linear), no light.
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() { f_color = material.color; }
