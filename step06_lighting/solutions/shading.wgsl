// Reference solution: the shading functions of step 06 in WGSL.

fn blinn_phong(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, radiance: vec3<f32>, albedo: vec3<f32>,
               specular: f32, shininess: f32) -> vec3<f32> {
    let n_dot_l = max(dot(n, l), 0.0);
    let h_sum = l + v;
    let h_length = length(h_sum);
    // l = -v (light straight behind the surface seen from the eye) has
    // no half vector; n_dot_l is 0 there anyway.
    let h = select(n, h_sum / max(h_length, 1e-6), h_length > 1e-6);
    // pow(0, 0) is undefined: shininess 0 means "no falloff", so the lobe is 1 everywhere.
    let lobe = select(1.0, pow(max(dot(n, h), 0.0), shininess), shininess > 0.0);
    return (albedo + specular * lobe) * radiance * n_dot_l;
}

fn reflect_direction(i: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    return i - 2.0 * dot(n, i) * n;
}

fn refract_direction(i: vec3<f32>, n: vec3<f32>, eta: f32) -> vec3<f32> {
    let cos_i = dot(n, i);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (k < 0.0) {
        return vec3<f32>(0.0);
    }
    return eta * i - (eta * cos_i + sqrt(k)) * n;
}
