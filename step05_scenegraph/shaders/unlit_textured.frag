#version 330 core
// The texture tinted by the material colour; no lighting (a sun shines by itself).
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;
out vec4 f_color;
void main() {
    f_color = material.color * texture(u_albedo, v_uv);
}
