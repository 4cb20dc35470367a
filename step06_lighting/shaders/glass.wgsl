// Ice or glass: the environment seen through one refraction, mixed
// with the reflection by Schlick's Fresnel.
#include "environment.wgsl"  // the vertex stage, the Material block, env and env_sampler

// --8<-- [start:fragment]
@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let i = safe_normalize(in.world - frame.camera_position.xyz, -n);
    let ior = max(material.ior, 1e-3);
    let r = reflect_direction(i, n);
    var t = refract_direction(i, n, 1.0 / ior);
    // Total internal reflection gives t = 0: a zero lookup direction is
    // undefined, so reflect instead.
    t = select(r, t, dot(t, t) > 1e-12);
    let f0 = (ior - 1.0) * (ior - 1.0) / ((ior + 1.0) * (ior + 1.0));
    let cos_i = clamp(-dot(i, n), 0.0, 1.0);
    let fresnel = f0 + (1.0 - f0) * pow(1.0 - cos_i, 5.0);
    // Both lookups happen in uniform control flow (textureSample needs it), then the mix picks.
    let refracted = material.color.rgb * textureSample(env, env_sampler, t).rgb;
    let reflected = textureSample(env, env_sampler, r).rgb;
    return vec4<f32>(mix(refracted, reflected, fresnel), 1.0);
}
// --8<-- [end:fragment]
