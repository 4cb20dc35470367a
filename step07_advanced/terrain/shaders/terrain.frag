#version 410 core
// Per fragment, from the uv alone: the normal
// (the exercise's terrain_normal), the height, the colour.
#include "frame.glsl"
#include "heightmap.glsl"
#include "terrain.glsl"
#include "terrain_shading.glsl"
in vec2 v_uv;
#include "material.glsl"  // the Material block, declared in Python with the shader
out vec4 f_color;
void main() {
    vec3 n = terrain_normal(v_uv, vec2(material.size, material.height_scale));
    float h = terrain_height(v_uv);
    vec3 world = vec3((v_uv.x - 0.5) * material.size, material.height_scale * h,
                      (v_uv.y - 0.5) * material.size);
    f_color = vec4(shade_terrain(h, n, world_to_relative(world), material.color.rgb), 1.0);
}
