#version 330 core
// World-space position, normal, UV and tangent for the step's surface shaders
// (pbr, bumpy, normal_view).
#include "frame.glsl"
#include "instance.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_tangent;  // xyz: along +u, w: handedness (glTF convention)
out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
void main() {
    mat4 model = instance_model();
    vec4 world = model * vec4(a_position, 1.0);
    v_world = world.xyz;
    v_normal = instance_normal(a_normal);
    v_uv = a_uv;
    // A tangent lies in the surface, so it follows the model matrix itself
    // (normals need the cofactor).
    v_tangent = vec4(mat3(model) * a_tangent.xyz, a_tangent.w);
    gl_Position = u_projection * u_view * world;
}
