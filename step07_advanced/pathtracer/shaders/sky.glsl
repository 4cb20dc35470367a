// The sky: the scene's cube map (linear RGB, faces +X -X +Y -Y +Z -Z, rows top first) read from a
// storage buffer with bilinear filtering inside each face, the same arithmetic as sky.wgsl and
// scene.sample_sky. Needs `sky_texels[]` and the Params block
// (u_background.w = face size, 0: the constant u_background.rgb).
// --8<-- [start:sky]
vec3 sky_texel(uint face, int row, int col, int size) {
    return sky_texels[(face * uint(size) + uint(row)) * uint(size) + uint(col)].rgb;
}

vec3 sky_radiance(vec3 d) {
    int size = int(u_background.w);
    if (size == 0) {
        return u_background.rgb;
    }
    vec3 a = abs(d);
    uint face;
    float ma, sc, tc;
    if (a.x >= a.y && a.x >= a.z) {
        face = d.x > 0.0 ? 0u : 1u; ma = a.x; sc = d.x > 0.0 ? -d.z : d.z; tc = -d.y;
    } else if (a.y >= a.z) {
        face = d.y > 0.0 ? 2u : 3u; ma = a.y; sc = d.x; tc = d.y > 0.0 ? d.z : -d.z;
    } else {
        face = d.z > 0.0 ? 4u : 5u; ma = a.z; sc = d.z > 0.0 ? d.x : -d.x; tc = -d.y;
    }
    float fx = 0.5 * (sc / ma + 1.0) * float(size) - 0.5;
    float fy = 0.5 * (tc / ma + 1.0) * float(size) - 0.5;
    float x0 = clamp(floor(fx), 0.0, float(size - 1));
    float y0 = clamp(floor(fy), 0.0, float(size - 1));
    float wx = clamp(fx - x0, 0.0, 1.0);
    float wy = clamp(fy - y0, 0.0, 1.0);
    int c0 = int(x0), r0 = int(y0);
    int c1 = min(c0 + 1, size - 1), r1 = min(r0 + 1, size - 1);
    vec3 top = mix(sky_texel(face, r0, c0, size), sky_texel(face, r0, c1, size), wx);
    vec3 bottom = mix(sky_texel(face, r1, c0, size), sky_texel(face, r1, c1, size), wx);
    return mix(top, bottom, wy);
}
// --8<-- [end:sky]
