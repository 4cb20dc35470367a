#version 330 core
// Test shader: Lambert lighting from the lights block.
#include "frame.glsl"
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 c = u_ambient.rgb * material.color.rgb;
    for (int i = 0; i < u_light_count.x; ++i) {
        c += material.color.rgb * u_light_color[i].rgb * max(dot(n,
            normalize(u_light_position[i].xyz)), 0.0);
    }
    f_color = vec4(c, 1.0);
}
