// Reference solution: the microfacet specular BRDF (Cook-Torrance with GGX) in GLSL.

const float BRDF_PI = 3.14159265358979;

// Schlick's approximation of the Fresnel reflectance at the angle whose cosine is cos_theta.
vec3 fresnel_schlick(float cos_theta, vec3 f0) {
    float m = clamp(1.0 - cos_theta, 0.0, 1.0);
    float m2 = m * m;
    return f0 + (1.0 - f0) * (m2 * m2 * m);
}

// Trowbridge-Reitz (GGX) normal distribution, alpha = roughness².
float distribution_ggx(float n_dot_h, float alpha) {
    float a2 = alpha * alpha;
    float d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
    return a2 / (BRDF_PI * d * d);
}

// Smith's shadowing-masking with the Schlick-GGX term per direction, k = (roughness + 1)² / 8 (direct light).
float geometry_smith(float n_dot_v, float n_dot_l, float roughness) {
    float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    return n_dot_v / (n_dot_v * (1.0 - k) + k) * n_dot_l / (n_dot_l * (1.0 - k) + k);
}

vec3 ggx_specular(vec3 n, vec3 v, vec3 l, float roughness, vec3 f0) {
    // Clamped cosines: at grazing angles n·v reaches 0 and the denominator with it.
    float n_dot_v = max(dot(n, v), 1e-4);
    float n_dot_l = max(dot(n, l), 1e-4);
    vec3 sum = l + v;
    float len = length(sum);
    vec3 h = len > 1e-6 ? sum / len : n;
    float n_dot_h = clamp(dot(n, h), 0.0, 1.0);
    float v_dot_h = clamp(dot(v, h), 0.0, 1.0);
    float d = distribution_ggx(n_dot_h, roughness * roughness);
    float g = geometry_smith(n_dot_v, n_dot_l, roughness);
    return d * g * fresnel_schlick(v_dot_h, f0) / (4.0 * n_dot_v * n_dot_l);
}
