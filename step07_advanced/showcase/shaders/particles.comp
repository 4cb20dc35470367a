#version 430 core
// The particle update as an OpenGL compute shader: one invocation per particle, 64 per work group.
// Compute shaders need GLSL 4.30 (the render shaders stay at 3.30).
// The same bytes as particles.wgsl:
// the parameters in a std140 uniform block, the particles in a std430 shader storage buffer.
layout(local_size_x = 64) in;

struct Particle {
    vec4 position;  // xyz: position, w: remaining life (s)
    vec4 velocity;  // xyz: velocity
};
// The SimParams struct (gravity, emitter, dt, restitution, floor_y, seed) and its uniform block
// `u_sim` (binding 4: 0 and 1 are the engine's Frame and Lights): declared once in shaders.py,
// written here by the engine.
#include "sim_params.glsl"
layout(std430, binding = 1) buffer Particles { Particle particles[]; };

#include "particle_step.glsl"

// A 32-bit integer hash (lowbias32): the same bits in GLSL, WGSL and numpy.
uint hash_u32(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

// A uniform float in [0, 1) from the hash's top 24 bits (exact in float32).
float random01(uint x) {
    return float(hash_u32(x) >> 8u) / 16777216.0;
}

// --8<-- [start:step]
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(particles.length())) {
        return;  // the last work group may be partly outside the buffer
    }
    Particle p = particle_step(particles[i], u_sim);
    if (p.position.w <= 0.0) {
        uint key = hash_u32(i ^ hash_u32(u_sim.seed)) & 0xfffffff0u;
        vec3 launch = vec3((random01(key) - 0.5) * 2.4, 5.0 + 1.5 * random01(key + 1u),
            (random01(key + 2u) - 0.5) * 2.4);
        p.position = vec4(u_sim.emitter.xyz, u_sim.emitter.w * (0.5 + 0.5 * random01(key + 3u)));
        p.velocity = vec4(launch, 0.0);
    }
    particles[i] = p;
}
// --8<-- [end:step]
