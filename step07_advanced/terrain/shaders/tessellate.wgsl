// WebGPU has no tessellation stage: this compute pass does its work, in three dispatches.
// cs_levels, one invocation per patch: the patch's levels from the exercise's tess_level, exactly
// as terrain.tesc computes them; the patch is cut into an n x n grid (n = ceil(inner)).
// cs_offsets, one invocation: where each patch's 6 n^2 vertices start (the patches in order), and
// their total, written as the vertex count of the indirect draw (nothing else is drawn).
// cs_main, one invocation per (cell, patch) of a fixed budget of L x L cells (L = the max level):
// the cells inside n x n write their 6 vertices, snapped on each edge to that edge's own
// ceil(outer) segments, so a neighbour with another inner level still meets it vertex for vertex.
#include "terrain.wgsl"

// Params (eye, lod, grid): declared once in shaders.py, written here by the engine.
#include "tessellate_params.wgsl"
@group(0) @binding(1) var heightmap: texture_2d<f32>;
@group(0) @binding(2) var<storage, read_write> vertices: array<vec4<f32>>;  // (u, v, world y, 1)
// per pid: outer[4]; (inner, n, 0, 0)
@group(0) @binding(3) var<storage, read_write> levels: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> offsets: array<u32>;  // per pid: its first vertex
// the indirect draw: (vertex count, instance count, first vertex, first instance); the renderer
// writes the last three
@group(0) @binding(5) var<storage, read_write> draw: array<u32>;
#include "heightmap_decode.wgsl"

fn corner_world(uv: vec2<f32>) -> vec3<f32> {
    let size = params.grid.x;
    return vec3<f32>((uv.x - 0.5) * size, params.grid.y * terrain_height(uv), (uv.y - 0.5) * size);
}

// Grid index i of n snapped to the nearest of m segments, in integers: floor(i m / n + 1/2) / m.
fn snap(i: u32, n: u32, m: u32) -> f32 {
    return f32((2u * i * m + n) / (2u * n)) / f32(m);
}

// --8<-- [start:tessellate]
fn patch_corners(pid: u32) -> array<vec2<f32>, 4> {
    let patches = u32(params.grid.z);
    let p = f32(patches);
    let pi = pid % patches;
    let pj = pid / patches;
    let uv0 = vec2<f32>(f32(pi) / p, f32(pj) / p);
    let uv1 = vec2<f32>(f32(pi + 1u) / p, f32(pj + 1u) / p);
    return array<vec2<f32>, 4>(uv0, vec2<f32>(uv1.x, uv0.y), uv1, vec2<f32>(uv0.x, uv1.y));
}

@compute @workgroup_size(64)
fn cs_levels(@builtin(global_invocation_id) gid: vec3<u32>) {
    let patches = u32(params.grid.z);
    let pid = gid.x;
    if (pid >= patches * patches) {
        return;
    }
    let c = patch_corners(pid);
    let w0 = corner_world(c[0]);
    let w1 = corner_world(c[1]);
    let w2 = corner_world(c[2]);
    let w3 = corner_world(c[3]);
    let eye = params.eye.xyz;
    // OpenGL's quad edges: 0 is u = u0, 1 is v = v0, 2 is u = u1, 3 is v = v1.
    let outer = vec4<f32>(tess_level(w0, w3, eye, params.lod.xyz),
                          tess_level(w0, w1, eye, params.lod.xyz),
                          tess_level(w1, w2, eye, params.lod.xyz),
                          tess_level(w3, w2, eye, params.lod.xyz));
    let inner = max(max(outer.x, outer.y), max(outer.z, outer.w));
    // Clamped, so that whatever tess_level returns (even NaN) the pass
    // stays inside the pid's budget.
    let n = clamp(u32(ceil(inner)), 1u, u32(params.grid.w));
    levels[2u * pid] = outer;
    levels[2u * pid + 1u] = vec4<f32>(inner, f32(n), 0.0, 0.0);
}

@compute @workgroup_size(1)
fn cs_offsets() {
    let patches = u32(params.grid.z);
    var total = 0u;
    for (var pid = 0u; pid < patches * patches; pid++) {
        offsets[pid] = total;
        let n = u32(levels[2u * pid + 1u].y);
        total += 6u * n * n;
    }
    draw[0] = total;
}

@compute @workgroup_size(64)
fn cs_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let patches = u32(params.grid.z);
    let budget = u32(params.grid.w);
    let cell = gid.x;
    let pid = gid.y;
    if (cell >= budget * budget || pid >= patches * patches) {
        return;
    }
    let n = u32(levels[2u * pid + 1u].y);
    let ci = cell % budget;
    let cj = cell / budget;
    if (ci >= n || cj >= n) {
        return;  // beyond this patch's grid: nothing is written, nothing is drawn
    }
    let m = clamp(vec4<u32>(ceil(levels[2u * pid])), vec4<u32>(1u), vec4<u32>(n));
    let c = patch_corners(pid);
    let base = offsets[pid] + (cj * n + ci) * 6u;
    var di = array<u32, 6>(0u, 1u, 1u, 0u, 1u, 0u);
    var dj = array<u32, 6>(0u, 0u, 1u, 0u, 1u, 1u);
    for (var k = 0u; k < 6u; k++) {
        let gi = ci + di[k];
        let gj = cj + dj[k];
        var s = f32(gi) / f32(n);
        var t = f32(gj) / f32(n);
        if (gj == 0u) { s = snap(gi, n, m.y); }
        if (gj == n) { s = snap(gi, n, m.w); }
        if (gi == 0u) { t = snap(gj, n, m.x); }
        if (gi == n) { t = snap(gj, n, m.z); }
        let uv = mix(mix(c[0], c[1], s), mix(c[3], c[2], s), t);
        vertices[base + k] = vec4<f32>(uv, params.grid.y * terrain_height(uv), 1.0);
    }
}
// --8<-- [end:tessellate]
