// Exercise 1: the microfacet specular BRDF in WGSL (included by the step's PBR shaders).
// Both functions return magenta until you write them. Keep them free of NaN for any input.

// Schlick's Fresnel: f0 + (1 - f0) * (1 - cos_theta)^5, with cos_theta clamped to [0, 1].
fn fresnel_schlick(cos_theta: f32, f0: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// The Cook-Torrance specular BRDF  D * G * F / (4 (n·v)(n·l))  for unit n, v (towards the eye), l (towards
// the light), roughness in [0.045, 1] and the reflectance at normal incidence f0:
//   D: GGX / Trowbridge-Reitz with alpha = roughness²:  alpha² / (pi ((n·h)² (alpha² - 1) + 1)²)
//   G: Smith with Schlick-GGX per direction, k = (roughness + 1)² / 8:  x / (x (1 - k) + k), x = n·v and n·l
//   F: fresnel_schlick(v·h, f0);  h = normalize(l + v) (use n when l + v = 0)
// Clamp n·v and n·l to at least 1e-4 so that grazing angles stay finite.
fn ggx_specular(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, roughness: f32, f0: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}
