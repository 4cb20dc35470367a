// The naive 2-D convolution: (2r + 1)^2 taps per pixel with the weights w(i) * w(j), clamp-to-edge.
#include "io.wgsl"

@compute @workgroup_size(16, 16)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let p = vec2<i32>(id.xy);
    let size = image_size();
    if (any(p >= size)) {
        return;
    }
    let r = params.radius;
    var sum = vec4<f32>(0.0);
    for (var j = -r; j <= r; j++) {
        var row = vec4<f32>(0.0);
        for (var i = -r; i <= r; i++) {
            row += weights[i + r] * textureLoad(src,
                clamp(p + vec2<i32>(i, j), vec2<i32>(0), size - 1), 0);
        }
        sum += weights[j + r] * row;
    }
    textureStore(dst, p, sum);
}
