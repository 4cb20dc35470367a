// Step 07 path tracer, WebGPU: one sample per pixel per dispatch, added to a float accumulation
// buffer. The scene (spheres, materials, the triangles in BVH order, the BVH nodes and the sky)
// sits in storage buffers that the CPU packed once (scene.py / bvh.py); pathtrace.comp is the same
// kernel in GLSL, line for line.

// --8<-- [start:bindings]
// Params (the camera, the background, the size and sample index, the counts): declared once in
// shaders.py, written here by the engine.
#include "pathtrace_params.wgsl"
// (centre, radius), (material, -, -, -)
@group(0) @binding(1) var<storage, read> spheres: array<vec4<f32>>;
// (albedo, kind), (fuzz, ior, -, -)
@group(0) @binding(2) var<storage, read> materials: array<vec4<f32>>;
// p0 (w: material), p1, p2, n0, n1, n2
@group(0) @binding(3) var<storage, read> triangles: array<vec4<f32>>;
// (bmin, first|right), (bmax, count)
@group(0) @binding(4) var<storage, read> nodes: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> sky_texels: array<vec4<f32>>; // linear RGB, 6 faces
// rgb: sum of samples, a: count
@group(0) @binding(6) var<storage, read_write> accum: array<vec4<f32>>;
// --8<-- [end:bindings]

#include "rng.wgsl"
#include "sky.wgsl"
#include "ray_sphere.wgsl"
#include "dielectric.wgsl"
#include "trace.wgsl"

// --8<-- [start:main]
@compute @workgroup_size(8, 8)
fn cs_main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if (gid.x >= params.size.x || gid.y >= params.size.y) {
        return;
    }
    let pixel = gid.y * params.size.x + gid.x;  // row 0 is the top of the picture
    var rng = rng_seed(pixel, params.size.z, params.size.w);
    let jx = rng_next(&rng);
    let jy = rng_next(&rng);
    let sx = 2.0 * (f32(gid.x) + jx) / f32(params.size.x) - 1.0;
    let sy = 1.0 - 2.0 * (f32(gid.y) + jy) / f32(params.size.y);
    let origin = params.origin.xyz;
    let dir = normalize(params.forward.xyz + sx * params.right.xyz + sy * params.up.xyz);
    let radiance = path_radiance(origin, dir, &rng);
    accum[pixel] = accum[pixel] + vec4<f32>(radiance, 1.0);
}
// --8<-- [end:main]
