#version 330 core
// Test shader: the material colour.
layout(std140) uniform Material {  // the material's values, the same bytes as WGSL's struct
    vec4 color;
} material;
out vec4 f_color;
void main() { f_color = material.color; }
