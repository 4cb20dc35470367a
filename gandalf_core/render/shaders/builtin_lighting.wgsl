// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "light_sample.wgsl"

fn gandalf_builtin_lighting(p: vec3<f32>, normal: vec3<f32>, albedo: vec3<f32>, specular: f32,
                            shininess: f32) -> vec3<f32> {
    let n = safe_normalize(normal, vec3<f32>(0.0, 1.0, 0.0));
    let v = safe_normalize(frame.camera_position.xyz - p, n);
    var total = lights.ambient.rgb * albedo;
    let count = min(lights.count.x, i32(MAX_LIGHTS));
    for (var i = 0; i < count; i++) {
        let s = light_at(i, p, n);
        let l = s.l;
        let radiance = s.radiance;
        let diffuse = max(dot(n, l), 0.0);
        let h = safe_normalize(l + v, n);
        let highlight = select(1.0, pow(max(dot(n, h), 0.0), shininess), shininess > 0.0);
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
