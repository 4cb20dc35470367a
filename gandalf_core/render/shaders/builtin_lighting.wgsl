// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "light_sample.wgsl"

fn gandalf_builtin_lighting(p: vec3<f32>, normal: vec3<f32>, albedo: vec3<f32>, specular: f32,
                            shininess: f32) -> vec3<f32> {
    let n_length = length(normal);
    let n = select(vec3<f32>(0.0, 1.0, 0.0), normal / max(n_length, 1e-12), n_length > 1e-12);
    let to_eye = frame.camera_position.xyz - p;
    let eye_distance = length(to_eye);
    let v = select(n, to_eye / max(eye_distance, 1e-12), eye_distance > 1e-12);
    var total = lights.ambient.rgb * albedo;
    let count = min(lights.count.x, i32(MAX_LIGHTS));
    for (var i = 0; i < count; i++) {
        let s = light_at(i, p, n);
        let l = s.l;
        let radiance = s.radiance;
        let diffuse = max(dot(n, l), 0.0);
        let h_sum = l + v;
        let h_length = length(h_sum);
        let h = select(n, h_sum / max(h_length, 1e-6), h_length > 1e-6);
        let highlight = select(1.0, pow(max(dot(n, h), 0.0), shininess), shininess > 0.0);
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
