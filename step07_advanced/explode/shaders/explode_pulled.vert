#version 430 core
// Vertex pulling in OpenGL (the study's third route): the WebGPU route's vertex shader in GLSL
// 4.30. The mesh drawn is 3·F attribute-less vertices; vertex k is corner k % 3 of triangle k / 3.
#include "frame.glsl"
#include "instance.glsl"
#include "explode.glsl"
layout(std430, binding = 0) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = 1) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = 2) readonly buffer Indices { uint indices[]; };
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec3 v_world;
out vec3 v_normal;
void main() {
    uint face = uint(gl_VertexID) / 3u;
    uint corner = uint(gl_VertexID) % 3u;
    mat4 model = instance_model();
    uint i0 = indices[3u * face];
    uint i1 = indices[3u * face + 1u];
    uint i2 = indices[3u * face + 2u];
    vec3 w0 = (model * vec4(positions[i0].xyz, 1.0)).xyz;
    vec3 w1 = (model * vec4(positions[i1].xyz, 1.0)).xyz;
    vec3 w2 = (model * vec4(positions[i2].xyz, 1.0)).xyz;
    vec3 offset = explode_offset(w0, w1, w2, material.explode_time, material.amount,
        material.period);
    uint index = corner == 0u ? i0 : (corner == 1u ? i1 : i2);
    v_world = (corner == 0u ? w0 : (corner == 1u ? w1 : w2)) + offset;
    v_normal = instance_normal(normals[index].xyz);
    gl_Position = u_projection * u_view * vec4(v_world, 1.0);
}
