#version 330 core
// The unexploded reference: the same surface as the explode program without the geometry stage.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_world;
out vec3 v_normal;
void main() {
    v_world = (instance_model() * vec4(a_position, 1.0)).xyz;
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * vec4(v_world, 1.0);
}
