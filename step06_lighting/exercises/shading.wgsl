// Exercise: the shading functions of step 06 in WGSL (included by the step's shaders).
// Every function returns magenta until you write it. Keep them free of NaN for any input.

// One light's contribution (linear RGB) at a surface point, Blinn-Phong:
//     (albedo * max(n·l, 0) + specular * max(n·h, 0)^shininess * max(n·l, 0)) * radiance,
//     h = normalize(l + v)
// n: unit normal, l: unit direction towards the light, v: unit direction towards the eye,
// radiance: the light's linear colour × intensity × attenuation.
// Shininess may be 0 (pow(0, 0)!) or 1e4.
fn blinn_phong(n: vec3<f32>, l: vec3<f32>, v: vec3<f32>, radiance: vec3<f32>, albedo: vec3<f32>,
               specular: f32, shininess: f32) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// The mirror direction of the incident direction i (eye -> surface) about the unit normal n.
fn reflect_direction(i: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// The refracted direction for unit i and n and eta = n1 / n2; the
// zero vector on total internal reflection.
fn refract_direction(i: vec3<f32>, n: vec3<f32>, eta: f32) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}
