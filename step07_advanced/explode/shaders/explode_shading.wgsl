// Two-sided Blinn-Phong with every light of the scene (the same sums as explode_shading.glsl), the material's
// uniform struct and the fragment stage both WGSL surface shaders of the technique share.
#include "frame.wgsl"

struct Material {
    color: vec4<f32>,
    explode_time: f32,  // seconds on the explosion clock (set every frame by ExplodeSystem)
    amount: f32,        // how far a face moves at the peak (world units)
    period: f32,        // seconds from one whole mesh to the next
    specular: f32,
    shininess: f32,
};
@group(1) @binding(0) var<uniform> material: Material;

struct SurfaceOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

fn shade(p: vec3<f32>, normal: vec3<f32>, albedo: vec3<f32>, specular: f32, shininess: f32) -> vec3<f32> {
    let nlen = length(normal);
    var n = select(vec3<f32>(0.0, 1.0, 0.0), normal / max(nlen, 1e-12), nlen > 1e-12);
    let d = frame.camera_position.xyz - p;
    let v = select(n, normalize(d), length(d) > 1e-12);
    // Flying triangles show their inner sides: light a back face as if it faced the camera.
    if (dot(n, v) < 0.0) {
        n = -n;
    }
    var color = lights.ambient.rgb * albedo;
    let count = min(lights.count.x, i32(MAX_LIGHTS));
    for (var i = 0; i < count; i++) {
        let position = lights.position[i];
        var radiance = lights.color[i].rgb;
        var l = position.xyz;  // directional: a unit vector towards the light
        if (position.w > 0.5) {
            let to_light = position.xyz - p;
            let distance = max(length(to_light), 1e-6);
            l = to_light / distance;
            let range = lights.color[i].a;
            if (range > 0.0) {
                let x = distance / range;
                let window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
                radiance *= window * window / max(distance * distance, 1e-4);
            }
        }
        let ndl = max(dot(n, l), 0.0);
        let h = normalize(l + v);
        let spec = specular * pow(max(dot(n, h), 0.0), shininess) * ndl;
        color += (albedo * ndl + spec) * radiance;
    }
    return color;
}

@fragment
fn fs_main(in: SurfaceOut) -> @location(0) vec4<f32> {
    return vec4<f32>(shade(in.world, in.normal, material.color.rgb, material.specular, material.shininess), 1.0);
}
