// Reference solution: decoding a tangent-space normal map with the TBN frame, in GLSL.

vec3 perturb_normal(vec3 n, vec4 tangent, vec3 map_rgb) {
    vec3 m = map_rgb * 2.0 - 1.0;
    // Gram-Schmidt: interpolation leaves the tangent slightly off the normal's plane.
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    float t_length = length(t);
    if (t_length > 1e-6) {
        t /= t_length;
    } else {
        // No usable tangent (zero, or parallel to n): any perpendicular keeps the result finite.
        vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0);
        t = normalize(axis - n * dot(n, axis));
    }
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 r = t * m.x + b * m.y + n * m.z;
    float r_length = length(r);
    return r_length > 1e-6 ? r / r_length : n;
}
