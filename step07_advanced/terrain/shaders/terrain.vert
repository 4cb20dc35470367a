#version 410 core
// The patch's control points go through unchanged: the tessellation stages place the vertices.
// --8<-- [start:vert]
layout(location = 2) in vec2 a_uv;
out vec2 vc_uv;
void main() {
    vc_uv = a_uv;
}
// --8<-- [end:vert]
