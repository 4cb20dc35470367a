#version 330 core
// Step 03: the material colour times one texture, sampled at the interpolated UV.
in vec2 v_uv;

#include "material.glsl"  // the Material block, declared in Python with the shader
uniform sampler2D u_albedo;  // the material's first texture; its sampler state
                             // comes with it in OpenGL

out vec4 f_color;

void main() {
    // An sRGB texture is decoded to linear light by the sampler, before filtering.
    f_color = material.color * texture(u_albedo, v_uv);
}
