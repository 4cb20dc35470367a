#version 330 core
// OpenGL route, stage 1 of 3: the model matrix only; the geometry
// shader explodes the whole triangle.
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 g_world;
out vec3 g_normal;
void main() {
    g_world = (instance_model() * vec4(a_position, 1.0)).xyz;
    g_normal = instance_normal(a_normal);
}
