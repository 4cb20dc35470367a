// Attack: an expression nested a hundred thousand brackets deep (Mesa's GLSL parser runs out of its stack).
vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}

vec3 explode_offset(vec3 p0, vec3 p1, vec3 p2, float t, float amount, float period) {
    float w = @@NESTED@@;
    return amount * w * face_normal(p0, p1, p2);
}
