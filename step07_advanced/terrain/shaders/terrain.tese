#version 410 core
// Tessellation evaluation: each generated vertex at its place in the
// patch, lifted by the heightmap.
#include "frame.glsl"
#include "heightmap.glsl"
#include "terrain.glsl"
// --8<-- [start:tese]
layout(quads, equal_spacing, ccw) in;
in vec2 tc_uv[];
out vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader

void main() {
    vec2 s = gl_TessCoord.xy;
    vec2 uv = mix(mix(tc_uv[0], tc_uv[1], s.x), mix(tc_uv[3], tc_uv[2], s.x), s.y);
    v_uv = uv;
    vec3 world = vec3((uv.x - 0.5) * material.size, material.height_scale * terrain_height(uv),
                      (uv.y - 0.5) * material.size);
    gl_Position = u_projection * u_view * vec4(world_to_relative(world), 1.0);
}
// --8<-- [end:tese]
