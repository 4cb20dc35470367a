// One brick material, four ways to read it: normal mapping only
// (method 0), simple parallax (1), steep parallax
// (2) and parallax occlusion mapping (3). Only the uv the maps are
//     sampled at differs; the shading is the same.
#include "surface_vertex.wgsl"
#include "parallax_shading.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader
@group(1) @binding(1) var albedo_map: texture_2d<f32>;
@group(1) @binding(2) var albedo_sampler: sampler;
@group(1) @binding(3) var normal_map: texture_2d<f32>;
@group(1) @binding(4) var normal_sampler: sampler;
@group(1) @binding(5) var height_map: texture_2d<f32>;
@group(1) @binding(6) var height_sampler: sampler;

// --8<-- [start:height_at]
// The exercise's functions read the height field through height_at(uv). Every
// sample uses the screen-space derivatives of the unshifted uv: the shifted uv
// jumps at the bricks' edges, and mip selection must not
// (textureSampleGrad is also what WGSL allows inside the march's non-uniform loop).
var<private> g_uv_dx: vec2<f32>;
var<private> g_uv_dy: vec2<f32>;
fn height_at(uv: vec2<f32>) -> f32 {
    return textureSampleGrad(height_map, height_sampler, uv, g_uv_dx, g_uv_dy).r;
}
#include "parallax.wgsl"
// --8<-- [end:height_at]

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    let n = normalize(in.normal);
    let v = normalize(frame.camera_position.xyz - in.world);
    // The tangent frame: T along +u, B = cross(n, T) * w along image-up (= -v).
    let raw = in.tangent.xyz - n * dot(n, in.tangent.xyz);
    let axis = select(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(1.0, 0.0, 0.0), abs(n.x) < 0.9);
    let t = select(normalize(cross(axis, n)), raw / max(length(raw), 1e-6), length(raw) > 1e-6);
    let b = cross(n, t) * select(1.0, -1.0, in.tangent.w < 0.0);
    var uv = in.uv * material.uv_scale;
    g_uv_dx = dpdx(uv);
    g_uv_dy = dpdy(uv);
    // --8<-- [start:methods]
    // The view direction in texture space: x along +u, y along +v
    // (against B), z out of the surface.
    let view_ts = vec3<f32>(dot(v, t), -dot(v, b), dot(v, n));
    let method = i32(material.method + 0.5);
    let layers = i32(material.layers + 0.5);
    if (method == 1) {
        uv = parallax_offset(uv, view_ts, material.height_scale);
    } else if (method == 2) {
        uv = parallax_steep(uv, view_ts, material.height_scale, layers);
    } else if (method == 3) {
        uv = parallax_occlusion(uv, view_ts, material.height_scale, layers);
    }
    let albedo = material.color.rgb
        * textureSampleGrad(albedo_map, albedo_sampler, uv, g_uv_dx, g_uv_dy).rgb;
    let m = textureSampleGrad(normal_map, normal_sampler, uv, g_uv_dx, g_uv_dy).rgb * 2.0 - 1.0;
    let shading = normalize(t * m.x + b * m.y + n * m.z);
    // --8<-- [end:methods]
    return vec4<f32>(
        shade(in.world, shading, v, albedo, material.specular, material.shininess), 1.0);
}
