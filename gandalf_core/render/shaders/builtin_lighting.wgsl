// The engine's built-in lit material (gandalf.blinn_phong): ambient + every light of the lights
// block, each with the Blinn-Phong model. Self-contained on purpose: step 06's exercise asks you to
// write this model yourself.
#include "frame.wgsl"

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
        let position = lights.position[i];
        var radiance = lights.color[i].rgb;
        var l = position.xyz;  // directional (w = 0): a unit vector towards the light
        if (position.w > 0.5) {
            let d = position.xyz - p;
            let distance = length(d);
            l = select(n, d / max(distance, 1e-6), distance > 1e-6);
            let range = lights.color[i].a;
            if (range > 0.0) {  // windowed inverse square, zero at the range
                let x = distance / range;
                let window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
                radiance *= window * window / max(distance * distance, 1e-4);
            }
        }
        let diffuse = max(dot(n, l), 0.0);
        let h_sum = l + v;
        let h_length = length(h_sum);
        let h = select(n, h_sum / max(h_length, 1e-6), h_length > 1e-6);
        let highlight = select(1.0, pow(max(dot(n, h), 0.0), shininess), shininess > 0.0);
        total += (albedo + specular * highlight) * radiance * diffuse;
    }
    return total;
}
