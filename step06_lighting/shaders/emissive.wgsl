// A light's marker: its flat colour, unlit.
#include "lit_vertex.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    return vec4<f32>(material.color.rgb, 1.0);
}
