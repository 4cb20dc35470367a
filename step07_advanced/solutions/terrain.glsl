// Terrain exercises in GLSL (reference): the level of detail of a
// patch edge, and the heightfield's height and normal. Included by the
// terrain's tessellation shaders (OpenGL) and by the tests' harness.
//
// The including shader provides the heightmap, a square map of N x N texels:
//   int heightmap_size();                // N
//   float heightmap_texel(ivec2 texel);  // the height in [0, 1] of texel (column, row),
//                                        // for 0 <= column, row < N only

// --8<-- [start:tess_level]
// The tessellation level of the patch edge from a to b (world space) seen from the camera at eye.
// lod = (scale, min_level, max_level):  level = clamp(scale * |b - a| / d, min_level, max_level)
// with d = the distance from eye to the edge's midpoint (a + b) / 2: near edges get more segments.
// When d < 1e-6 (the camera on the midpoint) the level is max_level. Never NaN;
// tess_level(a, b) == tess_level(b, a).
float tess_level(vec3 a, vec3 b, vec3 eye, vec3 lod) {
    float d = distance(eye, 0.5 * (a + b));
    if (d < 1e-6) {
        return lod.z;
    }
    return clamp(lod.x * distance(a, b) / d, lod.y, lod.z);
}
// --8<-- [end:tess_level]

// --8<-- [start:terrain_height]
// The height in [0, 1] at uv (u, v in [0, 1]) by bilinear interpolation of the texels, whose
// centres lie at uv = (texel + 0.5) / N (u picks the column, v the row). Clamp addressing: texel
// indices outside [0, N - 1] read the nearest edge texel (never call heightmap_texel out of range),
// so any uv (also < 0 or > 1) gives a value.
float terrain_height(vec2 uv) {
    int n = heightmap_size();
    vec2 st = uv * float(n) - 0.5;
    vec2 base = floor(st);
    vec2 f = st - base;
    ivec2 p0 = clamp(ivec2(base), ivec2(0), ivec2(n - 1));
    ivec2 p1 = clamp(ivec2(base) + 1, ivec2(0), ivec2(n - 1));
    float h00 = heightmap_texel(p0);
    float h10 = heightmap_texel(ivec2(p1.x, p0.y));
    float h01 = heightmap_texel(ivec2(p0.x, p1.y));
    float h11 = heightmap_texel(p1);
    return mix(mix(h00, h10, f.x), mix(h01, h11, f.x), f.y);
}
// --8<-- [end:terrain_height]

// --8<-- [start:terrain_normal]
// The unit normal of the terrain y = height_scale * terrain_height(uv) over
// the square of side size in x and z (world x grows with u, world z with v),
// by central differences one texel (e = 1 / N) apart:
//   dh/du = (terrain_height(uv + (e, 0)) - terrain_height(uv - (e, 0))) / (2 e), dh/dv likewise,
//   normal = normalize(-height_scale / size * dh/du, 1, -height_scale / size * dh/dv).
// scale = (size, height_scale). A flat map gives exactly (0, 1, 0).
vec3 terrain_normal(vec2 uv, vec2 scale) {
    float e = 1.0 / float(heightmap_size());
    float du = (terrain_height(uv + vec2(e, 0.0)) - terrain_height(uv - vec2(e, 0.0))) / (2.0 * e);
    float dv = (terrain_height(uv + vec2(0.0, e)) - terrain_height(uv - vec2(0.0, e))) / (2.0 * e);
    float k = scale.y / scale.x;
    return normalize(vec3(-k * du, 1.0, -k * dv));
}
// --8<-- [end:terrain_normal]
