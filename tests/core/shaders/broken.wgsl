// A WGSL module with a type error on line 7.
#include "frame.wgsl"
@vertex fn vs_main(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    return vec4<f32>(0.0);
}
@fragment fn fs_main() -> @location(0) vec4<f32> {
    let x: f32 = vec3<f32>(1.0);
    return vec4<f32>(x);
}
