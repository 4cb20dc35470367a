// Exercise 1: the microfacet specular BRDF in GLSL (included by the step's PBR shaders).
// Both functions return magenta until you write them. Keep them free of NaN for any input.

// Schlick's Fresnel: f0 + (1 - f0) * (1 - cos_theta)^5, with cos_theta clamped to [0, 1].
vec3 fresnel_schlick(float cos_theta, vec3 f0) {
    return vec3(1.0, 0.0, 1.0);
}

// The Cook-Torrance specular BRDF  D * G * F / (4 (n·v)(n·l))  for unit n, v (towards the eye), l (towards
// the light), roughness in [0.045, 1] and the reflectance at normal incidence f0:
//   D: GGX / Trowbridge-Reitz with alpha = roughness²:  alpha² / (pi ((n·h)² (alpha² - 1) + 1)²)
//   G: Smith with Schlick-GGX per direction, k = (roughness + 1)² / 8:  x / (x (1 - k) + k), x = n·v and n·l
//   F: fresnel_schlick(v·h, f0);  h = normalize(l + v) (use n when l + v = 0)
// Clamp n·v and n·l to at least 1e-4 so that grazing angles stay finite.
vec3 ggx_specular(vec3 n, vec3 v, vec3 l, float roughness, vec3 f0) {
    return vec3(1.0, 0.0, 1.0);
}
