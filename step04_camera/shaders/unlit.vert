#version 330 core
// Unlit, textured: the camera's view and projection come from the Frame block.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec2 v_uv;
void main() {
    v_uv = a_uv;
    // Model -> world -> camera (view) -> clip (projection): read right to left.
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
