#version 430 core
// Step 07 path tracer, OpenGL: one attribute-less triangle that covers the screen
// (vertex pulling with no buffer at all: the corner comes from gl_VertexID). uv = (0, 0) is the
// top-left corner, as in display.wgsl.
out vec2 v_uv;

void main() {
    // (0,0), (2,0), (0,2)
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vec2 clip = corner * 2.0 - 1.0;
    v_uv = vec2(corner.x, 1.0 - corner.y);
    gl_Position = vec4(clip, 0.0, 1.0);
}
