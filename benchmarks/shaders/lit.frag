#version 330 core
// One fixed directional light plus ambient; the material colour tints it (linear light).
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    float diffuse = max(dot(normalize(v_normal), normalize(vec3(0.3, 0.5, 1.0))), 0.0);
    f_color = vec4(material.color.rgb * (0.15 + 0.85 * diffuse), material.color.a);
}
