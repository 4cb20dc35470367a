#version 410 core
// Test shader: passes the control points of a quad patch on to tessellation.
layout(location = 0) in vec3 a_position;
void main() { gl_Position = vec4(a_position, 1.0); }
