#version 330 core
// Built-in material gandalf.blinn_phong with a texture: the scene's
// lights on the colour times the texture.
#include "builtin_lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_texture;
out vec4 f_color;
void main() {
    vec4 albedo = material.color * texture(u_texture, v_uv);
    vec3 lit = gandalf_builtin_lighting(v_world, v_normal, albedo.rgb, material.specular,
        material.shininess);
    f_color = vec4(lit, albedo.a);
}
