#version 330 core
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    // Map each component from [-1, 1] to [0, 1].
    f_color = material.color * vec4(normalize(v_normal) * 0.5 + 0.5, 1.0);
}
