#version 330 core
// Texture times colour, lit like shaded.frag.
in vec3 v_normal;
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;
out vec4 f_color;
void main() {
    vec3 light = normalize(vec3(0.4, 0.8, 0.6));
    float lambert = max(dot(normalize(v_normal), light), 0.0);
    vec4 albedo = material.color * texture(u_albedo, v_uv);
    f_color = vec4(albedo.rgb * (0.3 + 0.7 * lambert), albedo.a);
}
