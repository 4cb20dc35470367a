#version 330 core
// pyGANDALF comparison: Blinn-Phong, world-space (camera-relative) position and normal per vertex.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_position;
out vec3 v_normal;
void main() {
    vec4 world = instance_model() * vec4(a_position, 1.0);
    v_position = world.xyz;
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * world;
}
