// Two-sided Blinn-Phong with every light of the scene (the same sums as explode_shading.glsl) and
// the fragment stage both WGSL surface shaders of the technique share.
#include "frame.wgsl"
#include "../../shaders/blinn_phong.wgsl"

// The including file includes "material.wgsl", the Material block declared in Python
// (shaders.py: color, specular and shininess at @group(1) @binding(0)):
// the exploding shader's has the explosion's values too, the
// unexploded reference's only what it reads.

struct SurfaceOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

fn shade(p: vec3<f32>, normal: vec3<f32>, albedo: vec3<f32>, specular: f32,
    shininess: f32) -> vec3<f32> {
    let nlen = length(normal);
    var n = select(vec3<f32>(0.0, 1.0, 0.0), normal / max(nlen, 1e-12), nlen > 1e-12);
    let d = frame.camera_position.xyz - p;
    let v = select(n, normalize(d), length(d) > 1e-12);
    // Flying triangles show their inner sides: light a back face as if it faced the camera.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    return blinn_phong_lights(p, n, v, albedo, specular, shininess);
}

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    return vec4<f32>(shade(in.world, in.normal, material.color.rgb, material.specular,
        material.shininess), 1.0);
}
