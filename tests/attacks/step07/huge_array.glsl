// Attack: a local array of 200,000 floats filled on every call (the driver stalls compiling or running it).
vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
    return normalize(cross(p1 - p0, p2 - p0));
}

vec3 explode_offset(vec3 p0, vec3 p1, vec3 p2, float t, float amount, float period) {
    float big[200000];
    for (int i = 0; i < 200000; i++) {
        big[i] = t * float(i);
    }
    return amount * big[int(abs(t) * 7919.0) % 200000] * face_normal(p0, p1, p2);
}
