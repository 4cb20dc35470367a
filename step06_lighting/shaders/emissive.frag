#version 330 core
// A light's marker: its flat colour, unlit.
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    f_color = vec4(material.color.rgb, 1.0);
}
