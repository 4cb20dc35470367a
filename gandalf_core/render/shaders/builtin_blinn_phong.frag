#version 330 core
// Built-in material gandalf.blinn_phong, colour only: the scene's lights on the material colour.
#include "builtin_lighting.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 lit = gandalf_builtin_lighting(v_world, v_normal, material.color.rgb, material.specular,
        material.shininess);
    f_color = vec4(lit, material.color.a);
}
