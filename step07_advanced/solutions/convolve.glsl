// Reference solution: one pass of the separable blur at pixel p (image filter, exercise 2) in GLSL.

vec4 blur_pass(ivec2 p, ivec2 dir, int radius) {
    ivec2 last = image_size() - 1;
    vec4 sum = vec4(0.0);
    for (int i = -radius; i <= radius; ++i) {
        // clamp-to-edge: a tap beyond the border reads the nearest edge pixel
        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, ivec2(0), last));
    }
    return sum;
}
