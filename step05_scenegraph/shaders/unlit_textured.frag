#version 330 core
// The texture tinted by the material colour; no lighting (a sun shines by itself).
in vec2 v_uv;
layout(std140) uniform Material {  // the material's values, the same bytes as WGSL's struct
    vec4 color;
} material;
uniform sampler2D u_albedo;
out vec4 f_color;
void main() {
    f_color = material.color * texture(u_albedo, v_uv);
}
