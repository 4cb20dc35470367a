// Metallic-roughness PBR: base colour, metallic and roughness per
// material, lights plus the sky as environment.
#include "surface_vertex.wgsl"
#include "pbr_lighting.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var env: texture_cube<f32>;
@group(1) @binding(2) var env_sampler: sampler;

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    let shadow = shadow_factor(in.world, n);
    var color = pbr_direct(in.world, n, v, material.color.rgb, material.metallic,
        material.roughness, shadow);
    color += material.env_strength
        * pbr_environment(env, env_sampler, n, v, material.color.rgb, material.metallic,
            material.roughness);
    return vec4<f32>(color, 1.0);
}
