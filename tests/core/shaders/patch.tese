#version 410 core
// Test shader: bilinear interpolation of the quad's corners
// (0, 1, 2, 3 counter-clockwise), then a dome.
#include "frame.glsl"
layout(quads, equal_spacing, ccw) in;
void main() {
    vec2 uv = gl_TessCoord.xy;
    vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, uv.x);
    vec4 b = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, uv.x);
    vec4 p = mix(a, b, uv.y);
    gl_Position = u_projection * u_view * vec4(world_to_relative(p.xyz), 1.0);
}
