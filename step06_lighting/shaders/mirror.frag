#version 330 core
// A mirror (the silver bunny): the environment seen in the reflected
// direction, tinted by the colour.
#include "lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform samplerCube u_env;
out vec4 f_color;
void main() {
    vec3 n = safe_normalize(v_normal, vec3(0.0, 1.0, 0.0));
    vec3 i = safe_normalize(v_world - u_camera_position.xyz, -n);
    vec3 r = reflect_direction(i, n);
    f_color = vec4(material.color.rgb * texture(u_env, r).rgb, 1.0);
}
