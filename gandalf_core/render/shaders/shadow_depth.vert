#version 330 core
// The shadow pass: each opaque surface's depth as the shadow-casting light sees it (no colour).
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
void main() {
    gl_Position = u_light_view_projection * instance_model() * vec4(a_position, 1.0);
}
