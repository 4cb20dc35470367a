#version 330 core
// Metallic-roughness PBR: base colour, metallic and roughness per
// material, lights plus the sky as environment.
#include "pbr_lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform samplerCube u_env;
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    vec3 color = pbr_direct(v_world, n, v, material.color.rgb, material.metallic,
                            material.roughness, shadow_factor(v_world, n));
    color += material.env_strength
             * pbr_environment(u_env, n, v, material.color.rgb, material.metallic,
                 material.roughness);
    f_color = vec4(color, 1.0);
}
