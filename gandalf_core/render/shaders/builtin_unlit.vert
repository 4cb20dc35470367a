#version 330 core
// Built-in material gandalf.unlit, colour only: positions alone.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
void main() { gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0); }
