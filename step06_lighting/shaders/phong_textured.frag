#version 330 core
// Blinn-Phong whose albedo is the material colour times its texture.
#include "lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    vec3 albedo = material.color.rgb * texture(u_albedo, v_uv).rgb;
    f_color = vec4(shade(v_world, n, v, albedo, material.specular, material.shininess), 1.0);
}
