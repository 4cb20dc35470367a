// What the mirror and the glass share: the lit vertex stage, the lighting helpers, the Material block and the
// environment cube map (binding 1) with its sampler.
#include "lit_vertex.wgsl"
#include "lighting.wgsl"
#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var env: texture_cube<f32>;
@group(1) @binding(2) var env_sampler: sampler;
