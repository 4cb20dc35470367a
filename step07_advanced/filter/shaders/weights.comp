#version 430
// The weight table on the GPU: one invocation per tap, each calls the student's gaussian_weight.
layout(local_size_x = 64) in;
layout(std430, binding = 0) writeonly buffer Weights { float weights[]; };
#include "filter_params.glsl"

#include "blur_kernel.glsl"

void main() {
    int k = int(gl_GlobalInvocationID.x);
    if (k > 2 * u_radius) return;
    weights[k] = gaussian_weight(k - u_radius, u_radius);
}
