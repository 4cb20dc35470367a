#version 330 core
// The shading normal of a normal-mapped surface as a colour (n · 0.5 + 0.5): a debug view, and how
// the normal_map exercise is graded.
#include "normal_map.glsl"
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
uniform sampler2D u_normal_map;
out vec4 f_color;
void main() {
    float len = length(v_normal);
    vec3 n = len > 1e-12 ? v_normal / len : vec3(0.0, 1.0, 0.0);
    vec3 shading = perturb_normal(n, v_tangent, texture(u_normal_map, v_uv).rgb);
    f_color = vec4(shading * 0.5 + 0.5, 1.0);
}
