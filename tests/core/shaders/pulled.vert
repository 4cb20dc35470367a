#version 430 core
// Test shader: vertex pulling. Each vertex reads its position from a storage buffer by gl_VertexID.
#include "frame.glsl"
#include "instance.glsl"
layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
void main() {
    gl_Position = u_projection * u_view * instance_model() * vec4(positions[gl_VertexID].xyz, 1.0);
}
