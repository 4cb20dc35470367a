#version 430
// Step 07 path tracer, OpenGL: one sample per pixel per dispatch, added to a float accumulation
// buffer. The scene (spheres, materials, the triangles in BVH order, the BVH nodes and the sky)
// sits in storage buffers that the CPU packed once (scene.py / bvh.py); pathtrace.wgsl is the same
// kernel in WGSL, line for line.
layout(local_size_x = 8, local_size_y = 8) in;

// --8<-- [start:bindings]
// Params (the camera, the background, the size and sample index, the counts; binding 4: 0 and 1
// are the engine's Frame and Lights): declared once in shaders.py, written here by the engine.
#include "pathtrace_params.glsl"
// (centre, radius), (material, -, -, -)
layout(std430, binding = 0) readonly buffer Spheres { vec4 spheres[]; };
// (albedo, kind), (fuzz, ior, -, -)
layout(std430, binding = 1) readonly buffer Materials { vec4 materials[]; };
// p0 (w: material), p1, p2, n0, n1, n2
layout(std430, binding = 2) readonly buffer Triangles { vec4 triangles[]; };
// (bmin, first|right), (bmax, count)
layout(std430, binding = 3) readonly buffer Nodes { vec4 nodes[]; };
layout(std430, binding = 4) readonly buffer Sky { vec4 sky_texels[]; };       // linear RGB, 6 faces
// rgb: sum of samples, a: count
layout(std430, binding = 5) buffer Accum { vec4 accum[]; };
// --8<-- [end:bindings]

#include "rng.glsl"
#include "sky.glsl"
#include "ray_sphere.glsl"
#include "dielectric.glsl"
#include "trace.glsl"

// --8<-- [start:main]
void main() {
    uvec2 gid = gl_GlobalInvocationID.xy;
    if (gid.x >= u_size.x || gid.y >= u_size.y) {
        return;
    }
    uint pixel = gid.y * u_size.x + gid.x;  // row 0 is the top of the picture
    uint rng = rng_seed(pixel, u_size.z, u_size.w);
    float jx = rng_next(rng);
    float jy = rng_next(rng);
    float sx = 2.0 * (float(gid.x) + jx) / float(u_size.x) - 1.0;
    float sy = 1.0 - 2.0 * (float(gid.y) + jy) / float(u_size.y);
    vec3 origin = u_origin.xyz;
    vec3 dir = normalize(u_forward.xyz + sx * u_right.xyz + sy * u_up.xyz);
    vec3 radiance = path_radiance(origin, dir, rng);
    accum[pixel] += vec4(radiance, 1.0);
}
// --8<-- [end:main]
