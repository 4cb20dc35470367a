#version 410 core
// Tessellation control: once per patch, the level of each edge from its
// displaced corners (the exercise's tess_level), and the inner level as the
// largest of them. Two patches sharing an edge compute the same level from
// the same two corners, so their edges have the same vertices: no cracks.
#include "frame.glsl"
#include "heightmap.glsl"
#include "terrain.glsl"
// --8<-- [start:tesc]
layout(vertices = 4) out;
in vec2 vc_uv[];
out vec2 tc_uv[];
#include "material.glsl"  // the Material block, declared in Python with the shader

vec3 corner(int i) {
    vec2 uv = vc_uv[i];
    return vec3((uv.x - 0.5) * material.size, material.height_scale * terrain_height(uv),
                (uv.y - 0.5) * material.size);
}

void main() {
    tc_uv[gl_InvocationID] = vc_uv[gl_InvocationID];
    if (gl_InvocationID == 0) {
        vec3 c0 = corner(0), c1 = corner(1), c2 = corner(2), c3 = corner(3);
        // The terrain is built at the world's origin; the frame's positions are camera-relative.
        vec3 eye = u_camera_position.xyz + u_origin_high.xyz + u_origin_low.xyz;
        // OpenGL's quad edges: 0 is u = u0, 1 is v = v0, 2 is u = u1, 3 is v = v1.
        float o0 = tess_level(c0, c3, eye, material.lod.xyz);
        float o1 = tess_level(c0, c1, eye, material.lod.xyz);
        float o2 = tess_level(c1, c2, eye, material.lod.xyz);
        float o3 = tess_level(c3, c2, eye, material.lod.xyz);
        gl_TessLevelOuter[0] = o0;
        gl_TessLevelOuter[1] = o1;
        gl_TessLevelOuter[2] = o2;
        gl_TessLevelOuter[3] = o3;
        float inner = max(max(o0, o1), max(o2, o3));
        gl_TessLevelInner[0] = inner;
        gl_TessLevelInner[1] = inner;
    }
}
// --8<-- [end:tesc]
