// PBR with an albedo texture, a tangent-space normal map and parallax
// occlusion mapping from a height map.
#include "surface_vertex.wgsl"
#include "pbr_lighting.wgsl"
#include "normal_map.wgsl"
#include "parallax.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;
@group(1) @binding(3) var normal_map: texture_2d<f32>;
@group(1) @binding(4) var normal_sampler: sampler;
@group(1) @binding(5) var height_map: texture_2d<f32>;
@group(1) @binding(6) var height_sampler: sampler;
@group(1) @binding(7) var env: texture_cube<f32>;
@group(1) @binding(8) var env_sampler: sampler;

// --8<-- [start:main]
@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    let uv0 = in.uv * material.uv_scale;
    let dx = dpdx(uv0);
    let dy = dpdy(uv0);
    let basis = tangent_basis(n, in.tangent);
    let v_ts = vec3<f32>(dot(v, basis.t), dot(v, basis.b), dot(v, n));
    let uv = parallax_uv(height_map, height_sampler, uv0, v_ts, material.height_scale, dx, dy);
    let base = material.color.rgb * textureSampleGrad(albedo, albedo_sampler, uv, dx, dy).rgb;
    let shading = perturb_normal(n, in.tangent,
        textureSampleGrad(normal_map, normal_sampler, uv, dx, dy).rgb);
    // The shadow map's bias follows the surface's own slope, not the bumps the normal map adds.
    let shadow = shadow_factor(in.world, n);
    var color = pbr_direct(in.world, shading, v, base, material.metallic, material.roughness,
        shadow);
    color += material.env_strength
        * pbr_environment(env, env_sampler, shading, v, base, material.metallic,
            material.roughness);
    return vec4<f32>(color, 1.0);
}
// --8<-- [end:main]
