#version 330 core
// The sky: one triangle covering the screen at the far plane; each
// pixel looks up its view direction.
#include "frame.glsl"
out vec3 v_direction;
void main() {
    vec2 uv = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    vec2 clip = uv * 2.0 - 1.0;
    v_direction = (u_clip_to_direction * vec4(clip, 1.0, 1.0)).xyz;
    gl_Position = vec4(clip, u_depth.y, 1.0);
}
