// The random numbers of the path tracer, bit for bit the same as rng.glsl: a PCG hash
// (PCG-RXS-M-XS, as in Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020) in 32-bit
// unsigned arithmetic (wrapping).
// --8<-- [start:rng]
fn pcg_hash(v: u32) -> u32 {
    let state = v * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// One stream per (pixel, sample, seed): frame k of the accumulation is sample k.
fn rng_seed(pixel: u32, sample_index: u32, seed: u32) -> u32 {
    return pcg_hash(pixel ^ pcg_hash(sample_index ^ pcg_hash(seed)));
}

// The next number in [0, 1): 24 random bits, exact in float32.
fn rng_next(state: ptr<function, u32>) -> f32 {
    *state = pcg_hash(*state);
    return f32(*state >> 8u) * (1.0 / 16777216.0);
}
// --8<-- [end:rng]

fn random_unit_vector(state: ptr<function, u32>) -> vec3<f32> {
    let z = 1.0 - 2.0 * rng_next(state);
    let r = sqrt(max(0.0, 1.0 - z * z));
    let phi = 6.283185307179586 * rng_next(state);
    return vec3<f32>(r * cos(phi), r * sin(phi), z);
}

fn random_in_unit_sphere(state: ptr<function, u32>) -> vec3<f32> {
    let d = random_unit_vector(state);
    return d * pow(rng_next(state), 1.0 / 3.0);
}
