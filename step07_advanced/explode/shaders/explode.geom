#version 330 core
// OpenGL route, stage 2 of 3: one triangle in, the same triangle moved along its face normal out.
#include "frame.glsl"
#include "explode.glsl"
// --8<-- [start:geometry]
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_world[];
in vec3 g_normal[];
out vec3 v_world;
out vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
void main() {
    // The student's function (exercises/ or solutions/explode.glsl):
    // the same offset for all three corners.
    vec3 offset = explode_offset(g_world[0], g_world[1], g_world[2],
                                 material.explode_time, material.amount, material.period);
    for (int i = 0; i < 3; ++i) {
        v_world = g_world[i] + offset;
        v_normal = g_normal[i];
        gl_Position = u_projection * u_view * vec4(v_world, 1.0);
        EmitVertex();
    }
    EndPrimitive();
}
// --8<-- [end:geometry]
