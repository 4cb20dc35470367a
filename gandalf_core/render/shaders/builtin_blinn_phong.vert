#version 330 core
// Built-in material gandalf.blinn_phong, colour only: world-space position and normal.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;
void main() {
    vec4 world = instance_model() * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * world;
}
