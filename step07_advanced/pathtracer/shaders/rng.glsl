// The random numbers of the path tracer, bit for bit the same as rng.wgsl: a PCG hash
// (PCG-RXS-M-XS, as in Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020) in 32-bit
// unsigned arithmetic (wrapping).
// --8<-- [start:rng]
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// One stream per (pixel, sample, seed): frame k of the accumulation is sample k.
uint rng_seed(uint pixel, uint sample_index, uint seed) {
    return pcg_hash(pixel ^ pcg_hash(sample_index ^ pcg_hash(seed)));
}

// The next number in [0, 1): 24 random bits, exact in float32.
float rng_next(inout uint state) {
    state = pcg_hash(state);
    return float(state >> 8u) * (1.0 / 16777216.0);
}
// --8<-- [end:rng]

vec3 random_unit_vector(inout uint state) {
    float z = 1.0 - 2.0 * rng_next(state);
    float r = sqrt(max(0.0, 1.0 - z * z));
    float phi = 6.283185307179586 * rng_next(state);
    return vec3(r * cos(phi), r * sin(phi), z);
}

vec3 random_in_unit_sphere(inout uint state) {
    vec3 d = random_unit_vector(state);
    return d * pow(rng_next(state), 1.0 / 3.0);
}
