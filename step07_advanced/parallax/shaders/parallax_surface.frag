#version 330 core
// One brick material, four ways to read it: normal mapping only
// (method 0), simple parallax (1), steep parallax
// (2) and parallax occlusion mapping (3). Only the uv the maps are
//     sampled at differs; the shading is the same.
#include "frame.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_tangent;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;
uniform sampler2D u_normal_map;
uniform sampler2D u_height_map;
out vec4 f_color;

// --8<-- [start:height_at]
// The exercise's functions read the height field through height_at(uv).
// Every sample uses the screen-space derivatives of the unshifted uv: the
// shifted uv jumps at the bricks' edges, and mip selection must not.
vec2 g_uv_dx;
vec2 g_uv_dy;
float height_at(vec2 uv) {
    return textureGrad(u_height_map, uv, g_uv_dx, g_uv_dy).r;
}
#include "parallax.glsl"
// --8<-- [end:height_at]
#include "parallax_shading.glsl"

void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(u_camera_position.xyz - v_world);
    // The tangent frame: T along +u, B = cross(n, T) * w along image-up (= -v).
    vec3 t = v_tangent.xyz - n * dot(n, v_tangent.xyz);
    vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0);
    t = length(t) > 1e-6 ? normalize(t) : normalize(cross(axis, n));
    vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
    vec2 uv = v_uv * material.uv_scale;
    g_uv_dx = dFdx(uv);
    g_uv_dy = dFdy(uv);
    // --8<-- [start:methods]
    // The view direction in texture space: x along +u, y along +v
    // (against B), z out of the surface.
    vec3 view_ts = vec3(dot(v, t), -dot(v, b), dot(v, n));
    int method = int(material.method + 0.5);
    int layers = int(material.layers + 0.5);
    if (method == 1) {
        uv = parallax_offset(uv, view_ts, material.height_scale);
    } else if (method == 2) {
        uv = parallax_steep(uv, view_ts, material.height_scale, layers);
    } else if (method == 3) {
        uv = parallax_occlusion(uv, view_ts, material.height_scale, layers);
    }
    vec3 albedo = material.color.rgb * textureGrad(u_albedo, uv, g_uv_dx, g_uv_dy).rgb;
    vec3 m = textureGrad(u_normal_map, uv, g_uv_dx, g_uv_dy).rgb * 2.0 - 1.0;
    vec3 shading = normalize(t * m.x + b * m.y + n * m.z);
    // --8<-- [end:methods]
    f_color = vec4(shade(v_world, shading, v, albedo, material.specular, material.shininess), 1.0);
}
