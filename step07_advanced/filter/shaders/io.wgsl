// The filter kernels' inputs in WGSL: the pass's parameters, the source image, the weight table and
// the output. The source is a sampled texture read with textureLoad
// (rgba8unorm input or rgba32float intermediate); the output is a write-only storage texture
// (OUT_FORMAT: rgba32float or rgba8unorm). WebGPU has no read-write storage textures without a
// feature, and no sRGB storage format: the filters treat the stored 8-bit values as data.
// Params (direction: (1, 0) horizontal pass, (0, 1) vertical; radius: 0..MAX_RADIUS): declared
// once in shaders.py, written here by the engine.
#include "filter_params.wgsl"
@group(0) @binding(1) var src: texture_2d<f32>;
@group(0) @binding(2) var<storage, read> weights: array<f32>;  // 2 * radius + 1 taps
@group(0) @binding(3) var dst: texture_storage_2d<OUT_FORMAT, write>;

// The image's size in pixels.
fn image_size() -> vec2<i32> {
    return vec2<i32>(textureDimensions(src));
}

// The pixel at p, exactly: a p outside the image gives magenta, so a missing clamp shows.
fn load_texel(p: vec2<i32>) -> vec4<f32> {
    if (any(p < vec2<i32>(0)) || any(p >= image_size())) {
        return vec4<f32>(1.0, 0.0, 1.0, 1.0);
    }
    return textureLoad(src, p, 0);
}

// The normalised weight of tap i (-radius <= i <= radius); 0 beyond.
fn kernel_weight(i: i32) -> f32 {
    if (abs(i) > params.radius) {
        return 0.0;
    }
    return weights[i + params.radius];
}
