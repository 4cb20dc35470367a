// Sobel edges: the luminance gradient with the 3x3 Sobel kernels, clamp-to-edge, |g| * 0.5 as grey.
#include "io.wgsl"

fn luma(p: vec2<i32>) -> f32 {
    let q = clamp(p, vec2<i32>(0), image_size() - 1);
    return dot(textureLoad(src, q, 0).rgb, vec3<f32>(0.2126, 0.7152, 0.0722));
}

@compute @workgroup_size(16, 16)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let p = vec2<i32>(id.xy);
    if (any(p >= image_size())) {
        return;
    }
    let a = luma(p + vec2<i32>(-1, -1));
    let b = luma(p + vec2<i32>(0, -1));
    let c = luma(p + vec2<i32>(1, -1));
    let d = luma(p + vec2<i32>(-1, 0));
    let f = luma(p + vec2<i32>(1, 0));
    let g = luma(p + vec2<i32>(-1, 1));
    let h = luma(p + vec2<i32>(0, 1));
    let k = luma(p + vec2<i32>(1, 1));
    let gx = (c + 2.0 * f + k) - (a + 2.0 * d + g);
    let gy = (g + 2.0 * h + k) - (a + 2.0 * b + c);
    let m = clamp(sqrt(gx * gx + gy * gy) * 0.5, 0.0, 1.0);
    textureStore(dst, p, vec4<f32>(m, m, m, 1.0));
}
