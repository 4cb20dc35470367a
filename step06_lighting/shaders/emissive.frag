#version 330 core
// A light's marker: its flat colour, unlit.
in vec3 v_world;
in vec3 v_normal;
layout(std140) uniform Material {  // the material's values, the same bytes as WGSL's struct
    vec4 color;
} material;
out vec4 f_color;
void main() {
    f_color = vec4(material.color.rgb, 1.0);
}
