// A mirror (the silver bunny): the environment seen in the reflected
// direction, tinted by the colour.
#include "environment.wgsl"  // the vertex stage, the Material block, env and env_sampler

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let i = safe_normalize(in.world - frame.camera_position.xyz, -n);
    let r = reflect_direction(i, n);
    return vec4<f32>(material.color.rgb * textureSample(env, env_sampler, r).rgb, 1.0);
}
