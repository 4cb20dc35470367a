// Reference solution: the metallic-roughness microfacet BRDF (Cook-Torrance with GGX) in WGSL.

const BRDF_PI: f32 = 3.14159265358979;
const BRDF_MIN_ROUGHNESS: f32 = 0.045;
const BRDF_MIN_COSINE: f32 = 1e-4;

// Trowbridge-Reitz (GGX) normal distribution D; perceptual roughness
// clamped to [0.045, 1], alpha = roughness².
fn distribution_ggx(n_dot_h: f32, roughness: f32) -> f32 {
    let r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);
    let a2 = r * r * r * r;
    let c = clamp(n_dot_h, 0.0, 1.0);
    let d = c * c * (a2 - 1.0) + 1.0;
    return a2 / (BRDF_PI * d * d);
}

// Schlick-GGX's k for direct (analytic) lights: (roughness + 1)² / 8 (Karis' remapping).
fn k_direct(roughness: f32) -> f32 {
    let r = clamp(roughness, 0.0, 1.0);
    return (r + 1.0) * (r + 1.0) / 8.0;
}

// Schlick-GGX's k for image-based light: alpha / 2 = roughness² / 2.
fn k_ibl(roughness: f32) -> f32 {
    let r = clamp(roughness, 0.0, 1.0);
    return r * r / 2.0;
}

// Smith's shadowing-masking G = G1(n·v) G1(n·l),
// G1(x) = x / (x (1 - k) + k), cosines clamped to [1e-4, 1].
fn geometry_smith(n_dot_v: f32, n_dot_l: f32, k: f32) -> f32 {
    let v = clamp(n_dot_v, BRDF_MIN_COSINE, 1.0);
    let l = clamp(n_dot_l, BRDF_MIN_COSINE, 1.0);
    return v / (v * (1.0 - k) + k) * (l / (l * (1.0 - k) + k));
}

// Schlick's approximation of the Fresnel reflectance, cos_theta clamped to [0, 1].
fn fresnel_schlick(cos_theta: f32, f0: vec3<f32>) -> vec3<f32> {
    let m = 1.0 - clamp(cos_theta, 0.0, 1.0);
    let m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Schlick's Fresnel for image-based light: rough surfaces reflect less at grazing angles (Lagarde).
fn fresnel_schlick_roughness(cos_theta: f32, f0: vec3<f32>, roughness: f32) -> vec3<f32> {
    let m = 1.0 - clamp(cos_theta, 0.0, 1.0);
    let m2 = m * m;
    return f0 + (max(vec3<f32>(1.0 - clamp(roughness, 0.0, 1.0)), f0) - f0) * (m2 * m2 * m);
}

// Metallic-roughness workflow: dielectrics reflect 4 %, metals their base colour.
fn base_reflectance(base: vec3<f32>, metallic: f32) -> vec3<f32> {
    return mix(vec3<f32>(0.04), base, clamp(metallic, 0.0, 1.0));
}

// The diffuse albedo: metals have none, and what Fresnel reflects is not scattered
// (divide by pi for the BRDF).
fn diffuse_albedo(base: vec3<f32>, metallic: f32, fresnel: vec3<f32>) -> vec3<f32> {
    return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);
}

// The Cook-Torrance specular BRDF  D G F / (4 (n·v)(n·l))  with k_direct.
fn ggx_specular(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, roughness: f32,
    f0: vec3<f32>) -> vec3<f32> {
    // Clamped cosines: at grazing angles n·v reaches 0 and the denominator with it.
    let n_dot_v = clamp(dot(n, v), BRDF_MIN_COSINE, 1.0);
    let n_dot_l = clamp(dot(n, l), BRDF_MIN_COSINE, 1.0);
    let sum = l + v;
    let len = length(sum);
    let h = select(n, sum / max(len, 1e-6), len > 1e-6);
    let d = distribution_ggx(dot(n, h), roughness);
    let g = geometry_smith(n_dot_v, n_dot_l, k_direct(roughness));
    return d * g * fresnel_schlick(dot(v, h), f0) / (4.0 * n_dot_v * n_dot_l);
}
