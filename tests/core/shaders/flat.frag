#version 330 core
// Test shader: the material colour.
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() { f_color = material.color; }
