#version 430
// Sobel edges: the luminance gradient with the 3x3 Sobel kernels, clamp-to-edge, |g| * 0.5 as grey.
layout(local_size_x = 16, local_size_y = 16) in;
#include "io.glsl"
layout(OUT_FORMAT, binding = 0) writeonly uniform image2D u_dst;

float luma(ivec2 p) {
    return dot(texelFetch(u_src, clamp(p, ivec2(0), image_size() - 1), 0).rgb,
        vec3(0.2126, 0.7152, 0.0722));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, image_size()))) return;
    float a = luma(p + ivec2(-1, -1)), b = luma(p + ivec2(0, -1)), c = luma(p + ivec2(1, -1));
    float d = luma(p + ivec2(-1, 0)), f = luma(p + ivec2(1, 0));
    float g = luma(p + ivec2(-1, 1)), h = luma(p + ivec2(0, 1)), k = luma(p + ivec2(1, 1));
    float gx = (c + 2.0 * f + k) - (a + 2.0 * d + g);
    float gy = (g + 2.0 * h + k) - (a + 2.0 * b + c);
    float m = clamp(sqrt(gx * gx + gy * gy) * 0.5, 0.0, 1.0);
    imageStore(u_dst, p, vec4(m, m, m, 1.0));
}
