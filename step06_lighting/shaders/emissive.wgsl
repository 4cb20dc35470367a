// A light's marker: its flat colour, unlit.
#include "lit_vertex.wgsl"

struct Material {
    color: vec4<f32>,
};
@group(1) @binding(0) var<uniform> material: Material;

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    return vec4<f32>(material.color.rgb, 1.0);
}
