#version 330 core
// Blinn-Phong with the engine's lights
// (positions relative to the camera, which sits at the origin).
#include "frame.glsl"
in vec3 v_position;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(-v_position);
    vec3 c = u_ambient.rgb * material.color.rgb;
    for (int i = 0; i < u_light_count.x; ++i) {
        vec4 p = u_light_position[i];
        vec3 l = p.w == 0.0 ? normalize(p.xyz) : normalize(p.xyz - v_position);
        vec3 h = normalize(l + v);
        float d = max(dot(n, l), 0.0);
        float s = d > 0.0 ? pow(max(dot(n, h), 0.0), 32.0) : 0.0;
        c += u_light_color[i].rgb * (material.color.rgb * d + vec3(0.3) * s);
    }
    f_color = vec4(c, material.color.a);
}
