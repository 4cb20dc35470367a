#version 430 core
// Step 07 path tracer, OpenGL: show the accumulation's mean,
// tonemapped; the sRGB framebuffer encodes it.
#include "tonemap.glsl"
layout(std430, binding = 0) readonly buffer Accum { vec4 accum[]; };  // the material's buffer 0
#include "material.glsl"  // the Material block, declared in Python with the shader
in vec2 v_uv;
out vec4 f_color;

void main() {
    // --8<-- [start:resolve]
    ivec2 size = ivec2(material.trace_width, material.trace_height);
    ivec2 pixel = clamp(ivec2(v_uv * vec2(size)), ivec2(0), size - 1);
    vec4 sum = accum[pixel.y * size.x + pixel.x];
    vec3 mean = sum.rgb / max(sum.a, 1.0);
    f_color = vec4(tonemap(mean * material.exposure), 1.0);
    // --8<-- [end:resolve]
}
