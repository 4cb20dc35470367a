// The shading normal of a normal-mapped surface as a colour (n · 0.5 + 0.5): a debug view, and how
// the normal_map exercise is graded.
#include "surface_vertex.wgsl"
#include "normal_map.wgsl"

@group(1) @binding(0) var normal_map: texture_2d<f32>;
@group(1) @binding(1) var normal_sampler: sampler;

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    let len = length(in.normal);
    let n = select(vec3<f32>(0.0, 1.0, 0.0), in.normal / max(len, 1e-12), len > 1e-12);
    let shading = perturb_normal(n, in.tangent,
        textureSample(normal_map, normal_sampler, in.uv).rgb);
    return vec4<f32>(shading * 0.5 + 0.5, 1.0);
}
