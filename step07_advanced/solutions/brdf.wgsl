// Reference solution: the microfacet specular BRDF (Cook-Torrance with GGX) in WGSL.

const BRDF_PI: f32 = 3.14159265358979;

// Schlick's approximation of the Fresnel reflectance at the angle whose cosine is cos_theta.
fn fresnel_schlick(cos_theta: f32, f0: vec3<f32>) -> vec3<f32> {
    let m = clamp(1.0 - cos_theta, 0.0, 1.0);
    let m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Trowbridge-Reitz (GGX) normal distribution, alpha = roughness².
fn distribution_ggx(n_dot_h: f32, alpha: f32) -> f32 {
    let a2 = alpha * alpha;
    let d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (BRDF_PI * d * d);
}

// Smith's shadowing-masking with the Schlick-GGX term per direction, k = (roughness + 1)² / 8 (direct light).
fn geometry_smith(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    return n_dot_v / (n_dot_v * (1.0 - k) + k) * n_dot_l / (n_dot_l * (1.0 - k) + k);
}

fn ggx_specular(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, roughness: f32, f0: vec3<f32>) -> vec3<f32> {
    // Clamped cosines: at grazing angles n·v reaches 0 and the denominator with it.
    let n_dot_v = max(dot(n, v), 1e-4);
    let n_dot_l = max(dot(n, l), 1e-4);
    let sum = l + v;
    let len = length(sum);
    let h = select(n, sum / max(len, 1e-6), len > 1e-6);
    let n_dot_h = clamp(dot(n, h), 0.0, 1.0);
    let v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    let d = distribution_ggx(n_dot_h, roughness * roughness);
    let g = geometry_smith(n_dot_v, n_dot_l, roughness);
    return d * g * fresnel_schlick(v_dot_h, f0) / (4.0 * n_dot_v * n_dot_l);
}
