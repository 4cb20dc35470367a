#version 330 core
// Stage 3 of 3: two-sided Blinn-Phong (explode_lit.frag is the unexploded reference's).
#include "explode_shading.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 lit = shade(v_world, v_normal, material.color.rgb, material.specular, material.shininess);
    f_color = vec4(lit, 1.0);
}
