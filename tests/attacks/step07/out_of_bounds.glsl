// Attack: reads a million elements past the end of a local array (and of the vertex's own inputs' range).
vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}

vec3 explode_offset(vec3 p0, vec3 p1, vec3 p2, float t, float amount, float period) {
    float table[4] = float[4](0.0, 0.25, 0.5, 1.0);
    int far = int(abs(t) * 1000.0) + 1000000;
    return amount * (table[far] + table[-far]) * face_normal(p0, p1, p2);
}
