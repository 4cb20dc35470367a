// Reference solution: the shading functions of step 06 in GLSL.

vec3 blinn_phong(vec3 n, vec3 l, vec3 v, vec3 radiance, vec3 albedo, float specular,
    float shininess) {
    float n_dot_l = max(dot(n, l), 0.0);
    vec3 h = l + v;
    float h_length = length(h);
    // l = -v (light straight behind the surface seen from the eye) has
    // no half vector; n_dot_l is 0 there anyway.
    h = h_length > 1e-6 ? h / h_length : n;
    // pow(0, 0) is undefined in GLSL: shininess 0 means "no falloff", so the lobe is 1 everywhere.
    float lobe = shininess > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 1.0;
    return (albedo + specular * lobe) * radiance * n_dot_l;
}

vec3 reflect_direction(vec3 i, vec3 n) {
    return i - 2.0 * dot(n, i) * n;
}

vec3 refract_direction(vec3 i, vec3 n, float eta) {
    float cos_i = dot(n, i);
    float k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if (k < 0.0) {
        return vec3(0.0);
    }
    return eta * i - (eta * cos_i + sqrt(k)) * n;
}
