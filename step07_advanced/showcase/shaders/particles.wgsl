// The particle update as a WebGPU compute shader: one invocation per particle, 64 per work group.
// The same bytes as particles.comp: the parameters in a uniform
// buffer, the particles in a storage buffer.

struct Particle {
    position: vec4<f32>,  // xyz: position, w: remaining life (s)
    velocity: vec4<f32>,  // xyz: velocity
};
// SimParams (gravity, emitter, dt, restitution, floor_y, seed) and its uniform `sim`: declared
// once in shaders.py, written here by the engine.
#include "sim_params.wgsl"
@group(0) @binding(1) var<storage, read_write> particles: array<Particle>;

#include "particle_step.wgsl"

// A 32-bit integer hash (lowbias32): the same bits in GLSL, WGSL and numpy.
fn hash_u32(value: u32) -> u32 {
    var x = value;
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// A uniform float in [0, 1) from the hash's top 24 bits (exact in float32).
fn random01(x: u32) -> f32 {
    return f32(hash_u32(x) >> 8u) / 16777216.0;
}

// --8<-- [start:step]
@compute @workgroup_size(64)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if (i >= arrayLength(&particles)) {
        return;  // the last work group may be partly outside the buffer
    }
    var p = particle_step(particles[i], sim);
    if (p.position.w <= 0.0) {
        let key = hash_u32(i ^ hash_u32(sim.seed)) & 0xfffffff0u;
        let launch = vec3<f32>((random01(key) - 0.5) * 2.4, 5.0 + 1.5 * random01(key + 1u),
                               (random01(key + 2u) - 0.5) * 2.4);
        p.position = vec4<f32>(sim.emitter.xyz, sim.emitter.w * (0.5 + 0.5 * random01(key + 3u)));
        p.velocity = vec4<f32>(launch, 0.0);
    }
    particles[i] = p;
}
// --8<-- [end:step]
