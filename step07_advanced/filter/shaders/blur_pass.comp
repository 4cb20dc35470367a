#version 430
// One pass of the separable blur: every invocation writes one pixel with the student's blur_pass.
// --8<-- [start:kernel]
layout(local_size_x = 16, local_size_y = 16) in;
#include "io.glsl"
layout(OUT_FORMAT, binding = 0) writeonly uniform image2D u_dst;

#include "convolve.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, image_size()))) return;  // the last groups hang over
                                                         // the image's edge
    imageStore(u_dst, p, blur_pass(p, u_direction, u_radius));
}
// --8<-- [end:kernel]
