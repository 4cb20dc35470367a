// Blinn-Phong with every light of the scene and a per-material colour.
#include "lit_vertex.wgsl"
#include "lighting.wgsl"

#include "material.wgsl"  // the Material block, declared in Python with the shader

@fragment
fn fs_main(in: LitOut) -> @location(0) vec4<f32> {
    let n = safe_normalize(in.normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - in.world, n);
    return vec4<f32>(shade(in.world, n, v, material.color.rgb, material.specular,
        material.shininess), 1.0);
}
