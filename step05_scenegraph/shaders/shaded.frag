#version 330 core
// One colour, lit by a fixed world-space light: ambient 0.3 plus Lambert 0.7 (in linear light).
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 light = normalize(vec3(0.4, 0.8, 0.6));
    float lambert = max(dot(normalize(v_normal), light), 0.0);
    f_color = vec4(material.color.rgb * (0.3 + 0.7 * lambert), material.color.a);
}
