#version 330 core
// The fragment stage of the unexploded reference: two-sided
// Blinn-Phong (the same as explode.frag's, with only the shading
// values in its Material block, as explode_lit.wgsl's).
#include "explode_shading.glsl"
in vec3 v_world;
in vec3 v_normal;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 lit = shade(v_world, v_normal, material.color.rgb, material.specular, material.shininess);
    f_color = vec4(lit, 1.0);
}
