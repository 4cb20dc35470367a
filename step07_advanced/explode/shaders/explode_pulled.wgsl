// WebGPU route: vertex pulling. The mesh drawn is 3·F attribute-less
// vertices; vertex k is corner k % 3 of triangle k / 3, whose three
// corners this shader reads from storage buffers, explodes and outputs.
#include "explode_shading.wgsl"
#include "instance.wgsl"
#include "explode.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader

// --8<-- [start:pulling]
// xyz: model-space corner, w: 1
@group(1) @binding(1) var<storage, read> positions: array<vec4<f32>>;
// xyz: model-space vertex normal
@group(1) @binding(2) var<storage, read> normals: array<vec4<f32>>;
@group(1) @binding(3) var<storage, read> indices: array<u32>;          // three per triangle

fn corner_world(model: mat4x4<f32>, index: u32) -> vec3<f32> {
    return (model * vec4<f32>(positions[index].xyz, 1.0)).xyz;
}

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32, inst: Instance) -> SurfaceOut {
    let face = vertex / 3u;
    let corner = vertex % 3u;
    let model = instance_model(inst);
    let i0 = indices[3u * face];
    let i1 = indices[3u * face + 1u];
    let i2 = indices[3u * face + 2u];
    let w0 = corner_world(model, i0);
    let w1 = corner_world(model, i1);
    let w2 = corner_world(model, i2);
    // The student's function (exercises/ or solutions/explode.wgsl):
    // every corner of a face computes the same.
    let offset = explode_offset(w0, w1, w2, material.explode_time, material.amount,
        material.period);
    let world = select(select(w2, w1, corner == 1u), w0, corner == 0u) + offset;
    let index = select(select(i2, i1, corner == 1u), i0, corner == 0u);
    var out: SurfaceOut;
    out.position = frame.projection * frame.view * vec4<f32>(world, 1.0);
    out.world = world;
    out.normal = instance_normal(inst, normals[index].xyz);
    return out;
}
// --8<-- [end:pulling]
