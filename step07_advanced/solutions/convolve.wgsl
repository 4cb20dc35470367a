// Reference solution: one pass of the separable blur at pixel p (image filter, exercise 2) in WGSL.

fn blur_pass(p: vec2<i32>, dir: vec2<i32>, radius: i32) -> vec4<f32> {
    let last = image_size() - 1;
    var sum = vec4<f32>(0.0);
    for (var i = -radius; i <= radius; i++) {
        // clamp-to-edge: a tap beyond the border reads the nearest edge pixel
        sum += kernel_weight(i) * load_texel(clamp(p + i * dir, vec2<i32>(0), last));
    }
    return sum;
}
