// The terrain in WebGPU: the vertex shader pulls the vertices the compute
// pass (tessellate.wgsl) wrote, by vertex_index (no vertex buffer); the
// fragment shader shades from the uv alone, as terrain.frag does.
#include "frame.wgsl"
#include "terrain.wgsl"
#include "terrain_shading.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var heightmap: texture_2d<f32>;
@group(1) @binding(2) var heightmap_sampler: sampler;  // unused: texels are read with textureLoad
// (u, v, world y, 1); unused slots 0
@group(1) @binding(3) var<storage, read> vertices: array<vec4<f32>>;
#include "heightmap_decode.wgsl"

struct TerrainOut {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

// --8<-- [start:pull]
@vertex
fn vs_main(@builtin(vertex_index) index: u32) -> TerrainOut {
    let v = vertices[index];
    let world = vec3<f32>((v.x - 0.5) * material.size, v.z, (v.y - 0.5) * material.size);
    var out: TerrainOut;
    out.position = frame.projection * frame.view * vec4<f32>(world_to_relative(world), 1.0);
    out.uv = v.xy;
    return out;
}
// --8<-- [end:pull]

@fragment
fn fs_main(in: TerrainOut) -> @location(0) vec4<f32> {
    let n = terrain_normal(in.uv, vec2<f32>(material.size, material.height_scale));
    let h = terrain_height(in.uv);
    let world = vec3<f32>((in.uv.x - 0.5) * material.size, material.height_scale * h,
        (in.uv.y - 0.5) * material.size);
    return vec4<f32>(shade_terrain(h, n, world_to_relative(world), material.color.rgb), 1.0);
}
