#version 330 core
// Normal-shaded and textured: what the house walls use.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 v_normal;
out vec2 v_uv;
void main() {
    v_normal = instance_normal(a_normal);
    v_uv = a_uv;
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
