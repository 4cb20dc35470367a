// A mirror (the silver bunny): the environment seen in the reflected
// direction, tinted by the colour.
#include "lit_vertex.wgsl"
#include "lighting.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var env: texture_cube<f32>;
@group(1) @binding(2) var env_sampler: sampler;

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let i = safe_normalize(in.world - frame.camera_position.xyz, -n);
    let r = reflect_direction(i, n);
    return vec4<f32>(material.color.rgb * textureSample(env, env_sampler, r).rgb, 1.0);
}
