// Exercise: the metallic-roughness microfacet BRDF in WGSL (included by the step's PBR shaders).
// Every function returns a neutral value (magenta for colours) until you write it.
// Rules graded for EVERY input, including roughness 0 and 1, cosines 0
// (grazing) and out of range, black base colours: the result is finite
// (no NaN/Inf: watch 0/0 and pow(0, 0)) and matches the formula below.
// A wrong or black picture? `python -m step07_advanced.webgpu --technique showcase --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").

// GGX / Trowbridge-Reitz normal distribution D(h) = alpha² / (pi ((n·h)² (alpha² - 1) + 1)²).
// Clamp the perceptual roughness to [0.045, 1] first and square
// it: alpha = roughness². Clamp n·h to [0, 1].
fn distribution_ggx(n_dot_h: f32, roughness: f32) -> f32 {
    return 0.0;
}

// Schlick-GGX's k for direct (analytic) lights:
// k = (roughness + 1)² / 8, roughness clamped to [0, 1].
fn k_direct(roughness: f32) -> f32 {
    return 0.0;
}

// Schlick-GGX's k for image-based light:
// k = alpha / 2 = roughness² / 2, roughness clamped to [0, 1].
fn k_ibl(roughness: f32) -> f32 {
    return 0.0;
}

// Smith's shadowing-masking G = G1(n·v) G1(n·l) with Schlick-GGX G1(x) = x / (x (1 - k) + k).
// Clamp both cosines to [1e-4, 1] first (k may be 0: then G = 1).
fn geometry_smith(n_dot_v: f32, n_dot_l: f32, k: f32) -> f32 {
    return 1.0;
}

// Schlick's Fresnel: f0 + (1 - f0) (1 - cos_theta)^5, with cos_theta clamped to [0, 1].
fn fresnel_schlick(cos_theta: f32, f0: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// Schlick's Fresnel for image-based light (Lagarde): f0 + (max(1 - roughness, f0) - f0)
// (1 - cos_theta)^5, cos_theta and roughness clamped to [0, 1] (max per channel).
fn fresnel_schlick_roughness(cos_theta: f32, f0: vec3<f32>, roughness: f32) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// Metallic-roughness workflow, the reflectance at normal incidence: F0 = mix(0.04, base, metallic)
// (dielectrics reflect 4 %, metals tint their reflection with the
// base colour); metallic clamped to [0, 1].
fn base_reflectance(base: vec3<f32>, metallic: f32) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// Metallic-roughness workflow, the diffuse albedo: base (1 - metallic) (1 - fresnel), metallic
// clamped to [0, 1]. Metals scatter no light diffusely; what Fresnel reflects is not scattered.
// (The Lambert BRDF is this albedo / pi; the shaders divide.)
fn diffuse_albedo(base: vec3<f32>, metallic: f32, fresnel: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}

// The Cook-Torrance specular BRDF  D G F / (4 (n·v)(n·l))  for unit n, v (towards the eye),
// l (towards the light), roughness in [0, 1] and f0, built from the functions above:
//   D = distribution_ggx(n·h, roughness);  G = geometry_smith(n·v, n·l, k_direct(roughness));
//   F = fresnel_schlick(v·h, f0);  h = normalize(l + v), or n when l + v = 0.
// Clamp n·v and n·l to [1e-4, 1] (also in the denominator) so that grazing angles stay finite.
fn ggx_specular(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, roughness: f32,
    f0: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(1.0, 0.0, 1.0);
}
