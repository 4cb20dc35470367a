#version 330 core
// Built-in material gandalf.unlit with a texture: positions and texture coordinates.
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_uv;
out vec2 v_uv;
void main() {
    v_uv = a_uv;
    gl_Position = u_projection * u_view * instance_model() * vec4(a_position, 1.0);
}
