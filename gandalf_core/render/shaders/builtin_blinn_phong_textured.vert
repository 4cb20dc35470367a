#version 330 core
// Built-in material gandalf.blinn_phong with a texture: world-space
// position, normal and texture coordinates.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
void main() {
    vec4 world = instance_model() * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = instance_normal(a_normal);
    v_uv = a_uv;
    gl_Position = u_projection * u_view * world;
}
