#version 330 core
// Ice or glass: the environment seen through one refraction, mixed
// with the reflection by Schlick's Fresnel.
#include "lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform samplerCube u_env;
out vec4 f_color;
// --8<-- [start:fragment]
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 i = safe_normalize(v_world - u_camera_position.xyz, -n);
    float ior = max(material.ior, 1e-3);
    vec3 r = reflect_direction(i, n);
    vec3 t = refract_direction(i, n, 1.0 / ior);
    // Total internal reflection gives t = 0: a zero lookup direction is
    // undefined, so reflect instead.
    t = dot(t, t) > 1e-12 ? t : r;
    float f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
    float cos_i = clamp(-dot(i, n), 0.0, 1.0);
    float fresnel = f0 + (1.0 - f0) * pow(1.0 - cos_i, 5.0);
    vec3 color = mix(material.color.rgb * texture(u_env, t).rgb, texture(u_env, r).rgb, fresnel);
    f_color = vec4(color, 1.0);
}
// --8<-- [end:fragment]
