// Step 02: positions and colours come from the vertex buffer; the instance rows place the shape.
#include "frame.wgsl"
#include "instance.wgsl"

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) color: vec4<f32>,  // linear light: interpolated across the triangle
};

// The exact sRGB decoding (IEC 61966-2-1): a straight line near black, a 2.4 power above.
fn srgb_to_linear(color: vec3<f32>) -> vec3<f32> {
    let c = clamp(color, vec3<f32>(0.0), vec3<f32>(1.0));
    return select(c / 12.92, pow((c + 0.055) / 1.055, vec3<f32>(2.4)), c > vec3<f32>(0.04045));
}

@vertex
fn vs_main(
    @location(0) position: vec3<f32>,
    @location(4) color: vec4<f32>,  // sRGB, like every colour in gandalf
    inst: Instance,
) -> VertexOut {
    var out: VertexOut;
    out.color = vec4<f32>(srgb_to_linear(color.rgb), color.a);
    // No camera in this step: view and projection are identity, so this is the clip-space position.
    out.position = frame.projection * frame.view * instance_model(inst) * vec4<f32>(position, 1.0);
    return out;
}

// Write the interpolated colour; the sRGB render target encodes it again.
@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return in.color;
}
