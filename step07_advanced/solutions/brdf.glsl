// Reference solution: the metallic-roughness microfacet BRDF (Cook-Torrance with GGX) in GLSL.

const float BRDF_PI = 3.14159265358979;
const float BRDF_MIN_ROUGHNESS = 0.045;
const float BRDF_MIN_COSINE = 1e-4;

// Trowbridge-Reitz (GGX) normal distribution D; perceptual roughness
// clamped to [0.045, 1], alpha = roughness².
float distribution_ggx(float n_dot_h, float roughness) {
    float r = clamp(roughness, BRDF_MIN_ROUGHNESS, 1.0);
    float a2 = r * r * r * r;
    float c = clamp(n_dot_h, 0.0, 1.0);
    float d = c * c * (a2 - 1.0) + 1.0;
    return a2 / (BRDF_PI * d * d);
}

// Schlick-GGX's k for direct (analytic) lights: (roughness + 1)² / 8 (Karis' remapping).
float k_direct(float roughness) {
    float r = clamp(roughness, 0.0, 1.0);
    return (r + 1.0) * (r + 1.0) / 8.0;
}

// Schlick-GGX's k for image-based light: alpha / 2 = roughness² / 2.
float k_ibl(float roughness) {
    float r = clamp(roughness, 0.0, 1.0);
    return r * r / 2.0;
}

// Smith's shadowing-masking G = G1(n·v) G1(n·l),
// G1(x) = x / (x (1 - k) + k), cosines clamped to [1e-4, 1].
float geometry_smith(float n_dot_v, float n_dot_l, float k) {
    float v = clamp(n_dot_v, BRDF_MIN_COSINE, 1.0);
    float l = clamp(n_dot_l, BRDF_MIN_COSINE, 1.0);
    return v / (v * (1.0 - k) + k) * (l / (l * (1.0 - k) + k));
}

// Schlick's approximation of the Fresnel reflectance, cos_theta clamped to [0, 1].
vec3 fresnel_schlick(float cos_theta, vec3 f0) {
    float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Schlick's Fresnel for image-based light: rough surfaces reflect less at grazing angles (Lagarde).
vec3 fresnel_schlick_roughness(float cos_theta, vec3 f0, float roughness) {
    float m = 1.0 - clamp(cos_theta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (max(vec3(1.0 - clamp(roughness, 0.0, 1.0)), f0) - f0) * (m2 * m2 * m);
}

// Metallic-roughness workflow: dielectrics reflect 4 %, metals their base colour.
vec3 base_reflectance(vec3 base, float metallic) {
    return mix(vec3(0.04), base, clamp(metallic, 0.0, 1.0));
}

// The diffuse albedo: metals have none, and what Fresnel reflects is not scattered
// (divide by pi for the BRDF).
vec3 diffuse_albedo(vec3 base, float metallic, vec3 fresnel) {
    return base * (1.0 - clamp(metallic, 0.0, 1.0)) * (1.0 - fresnel);
}

// The Cook-Torrance specular BRDF  D G F / (4 (n·v)(n·l))  with k_direct.
vec3 ggx_specular(vec3 n, vec3 v, vec3 l, float roughness, vec3 f0) {
    // Clamped cosines: at grazing angles n·v reaches 0 and the denominator with it.
    float n_dot_v = clamp(dot(n, v), BRDF_MIN_COSINE, 1.0);
    float n_dot_l = clamp(dot(n, l), BRDF_MIN_COSINE, 1.0);
    vec3 sum = l + v;
    float len = length(sum);
    vec3 h = len > 1e-6 ? sum / len : n;
    float d = distribution_ggx(dot(n, h), roughness);
    float g = geometry_smith(n_dot_v, n_dot_l, k_direct(roughness));
    return d * g * fresnel_schlick(dot(v, h), f0) / (4.0 * n_dot_v * n_dot_l);
}
