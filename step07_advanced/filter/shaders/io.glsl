// The filter kernels' inputs in GLSL: the source image, the weight table and the pass's parameters.
// The source is read with texelFetch (no filtering), so one declaration serves the rgba8 input and
// the rgba32f intermediate image; the output image's format is in each kernel
// (OUT_FORMAT: rgba32f or rgba8).
layout(binding = 0) uniform sampler2D u_src;
layout(std430, binding = 0) readonly buffer Weights { float weights[]; };  // 2 * u_radius + 1 taps
// The Params block (u_direction: (1, 0) horizontal pass, (0, 1) vertical; u_radius: 0..MAX_RADIUS):
// declared once in shaders.py, written here by the engine.
#include "filter_params.glsl"

// The image's size in pixels.
ivec2 image_size() { return textureSize(u_src, 0); }

// The pixel at p, exactly: a p outside the image gives magenta, so a missing clamp shows.
vec4 load_texel(ivec2 p) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, image_size())))
        return vec4(1.0, 0.0, 1.0, 1.0);
    return texelFetch(u_src, p, 0);
}

// The normalised weight of tap i (-u_radius <= i <= u_radius); 0 beyond.
float kernel_weight(int i) {
    if (abs(i) > u_radius) return 0.0;
    return weights[i + u_radius];
}
