// Step 07 path tracer, WebGPU: one attribute-less triangle that covers
// the screen shows the accumulation's mean, tonemapped; the sRGB target
// encodes it. uv = (0, 0) is the top-left corner, as in display.vert.
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var<storage, read> accum: array<vec4<f32>>;  // the material's buffer 0

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> VertexOut {
    let corner = vec2<f32>(f32((vertex << 1u) & 2u), f32(vertex & 2u));  // (0,0), (2,0), (0,2)
    var out: VertexOut;
    out.position = vec4<f32>(corner * 2.0 - 1.0, 0.0, 1.0);
    out.uv = vec2<f32>(corner.x, 1.0 - corner.y);
    return out;
}

fn tonemap(x_in: vec3<f32>) -> vec3<f32> {
    let x = max(x_in, vec3<f32>(0.0));
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14),
                 vec3<f32>(0.0), vec3<f32>(1.0));
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    // --8<-- [start:resolve]
    let size = vec2<i32>(i32(material.trace_width), i32(material.trace_height));
    let pixel = clamp(vec2<i32>(in.uv * vec2<f32>(size)), vec2<i32>(0), size - 1);
    let sum = accum[pixel.y * size.x + pixel.x];
    let mean = sum.rgb / max(sum.a, 1.0);
    return vec4<f32>(tonemap(mean * material.exposure), 1.0);
    // --8<-- [end:resolve]
}
