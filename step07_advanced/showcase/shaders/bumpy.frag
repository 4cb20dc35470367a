#version 330 core
// PBR with an albedo texture, a tangent-space normal map and parallax
// occlusion mapping from a height map.
#include "pbr_lighting.glsl"
#include "normal_map.glsl"
#include "parallax.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;
uniform sampler2D u_normal_map;
uniform sampler2D u_height_map;
uniform samplerCube u_env;
out vec4 f_color;
// --8<-- [start:main]
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 v = safe_normalize(u_camera_position.xyz - v_world, n);
    vec2 uv = v_uv * material.uv_scale;
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    vec3 t, b;
    tangent_basis(n, v_tangent, t, b);
    vec3 view_tangent = vec3(dot(v, t), dot(v, b), dot(v, n));
    uv = parallax_uv(u_height_map, uv, view_tangent, material.height_scale, dx, dy);
    vec3 base = material.color.rgb * textureGrad(u_albedo, uv, dx, dy).rgb;
    vec3 shading = perturb_normal(n, v_tangent, textureGrad(u_normal_map, uv, dx, dy).rgb);
    // The shadow map's bias follows the surface's own slope, not the bumps the normal map adds.
    float shadow = shadow_factor(v_world, n);
    vec3 color = pbr_direct(v_world, shading, v, base, material.metallic, material.roughness,
        shadow);
    color += material.env_strength
             * pbr_environment(u_env, shading, v, base, material.metallic, material.roughness);
    f_color = vec4(color, 1.0);
}
// --8<-- [end:main]
