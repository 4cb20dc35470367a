#version 330 core
// Test shader: Lambert lighting from the lights block.
#include "frame.glsl"
in vec3 v_normal;
uniform vec4 u_color;
out vec4 f_color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 c = u_ambient.rgb * u_color.rgb;
    for (int i = 0; i < u_light_count.x; ++i) c += u_color.rgb * u_light_color[i].rgb * max(dot(n, normalize(u_light_position[i].xyz)), 0.0);
    f_color = vec4(c, 1.0);
}
