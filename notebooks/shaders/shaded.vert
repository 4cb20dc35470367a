#version 330 core
// Normal-shaded: the normal goes to world space with instance_normal (correct under any scale).
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 v_normal;
void main() {
    v_normal = instance_normal(a_normal);
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
