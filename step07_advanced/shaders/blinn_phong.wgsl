// Blinn-Phong with every light of the scene, shared by step 07's lit techniques
// (explode, parallax); the same sums as blinn_phong.glsl. p: the shaded point, n: the unit normal,
// v: the unit vector towards the eye (camera-relative positions, as the engine's frame and lights
// blocks hold them). Needs frame.wgsl (the lights block) first.
fn blinn_phong_lights(p: vec3<f32>, n: vec3<f32>, v: vec3<f32>, albedo: vec3<f32>, specular: f32,
    shininess: f32) -> vec3<f32> {
    var color = lights.ambient.rgb * albedo;
    let count = min(u32(max(lights.count.x, 0)), MAX_LIGHTS);
    for (var i = 0u; i < count; i++) {
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
