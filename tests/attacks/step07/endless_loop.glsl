// Attack: explode_offset never returns (an even counter stepped by 2 never reaches 1).
vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}

vec3 explode_offset(vec3 p0, vec3 p1, vec3 p2, float t, float amount, float period) {
    uint i = uint(abs(t)) * 2u;
    while (i != 1u) {
        i += 2u;
    }
    return vec3(float(i)) * amount;
}
