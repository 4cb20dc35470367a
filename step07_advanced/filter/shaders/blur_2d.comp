#version 430
// The naive 2-D convolution: (2r + 1)^2 taps per pixel with the weights w(i) * w(j), clamp-to-edge.
layout(local_size_x = 16, local_size_y = 16) in;
#include "io.glsl"
layout(OUT_FORMAT, binding = 0) writeonly uniform image2D u_dst;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = image_size();
    if (any(greaterThanEqual(p, size))) return;
    vec4 sum = vec4(0.0);
    for (int j = -u_radius; j <= u_radius; ++j) {
        vec4 row = vec4(0.0);
        for (int i = -u_radius; i <= u_radius; ++i) {
            row += weights[i + u_radius] * texelFetch(u_src,
                clamp(p + ivec2(i, j), ivec2(0), size - 1), 0);
        }
        sum += weights[j + u_radius] * row;
    }
    imageStore(u_dst, p, sum);
}
