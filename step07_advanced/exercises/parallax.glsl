// Exercise parallax: simple, steep and occlusion parallax mapping, in GLSL
// (used by step07_advanced/parallax). All three return uv unchanged
// (flat, like plain normal mapping) until you write them.
// A wrong or black picture? `python -m step07_advanced.opengl --technique parallax --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// Conventions (the same in all three functions):
//   * height_at(uv) is the height field in [0, 1] (1 = the top surface, 0 = the deepest point); the
//     shader that includes this file defines it (GLSL: before the #include). The depth below the
//     top is 1 - height_at(uv).
//   * view_ts is the unit vector from the surface point towards the eye in TEXTURE space: x along
//     +u, y along +v, z out of the surface. Looking down a ray that leans towards +u you see points
//     that lie further towards -u, so every method moves uv AGAINST view_ts.xy.
//   * scale (>= 0, checked on the CPU) is the depth of height 0 in uv units.
//   * Divide by max(view_ts.z, PARALLAX_MIN_Z) (0.1), never by view_ts.z itself: at a grazing view
//     (z -> 0, or z < 0 from an interpolated normal) the result must stay finite.
//   * Do not clamp or wrap uv: the texture repeats, a shifted uv may leave [0, 1].
//
// parallax_offset(uv, view_ts, scale): simple parallax mapping
//     (one height sample, no offset limiting):
//     uv - view_ts.xy / max(view_ts.z, 0.1) * scale * (1 - height_at(uv))
// parallax_steep(uv, view_ts, scale, layers): steep parallax mapping.
//     n = clamp(layers, 1, PARALLAX_MAX_LAYERS); layer i = 0, 1, ..., n lies at depth i / n and at
//     uv_i = uv - i * step, step = view_ts.xy / max(view_ts.z, 0.1) * scale / n. Return uv_i of the
//     FIRST layer i whose depth is at or below the surface:
//     i / n >= 1 - height_at(uv_i). Layer 0 counts (a point at height 1 is not moved); layer n
//     (depth 1) always ends the march, so the loop runs at most n + 1 times.
// parallax_occlusion(uv, view_ts, scale, layers): parallax occlusion mapping:
//     the same march, then the linear interpolation between the last layer
//     above the surface (i - 1) and the first one at or below it (i):
//     with a = (1 - height_at(uv_{i-1})) - (i-1)/n  (> 0)
//     and  b = (1 - height_at(uv_i)) - i/n  (<= 0),
//     return uv_{i-1} - a / (a - b) * step   (= mix(uv_i, uv_{i-1}, b / (b - a))).
//     If layer 0 already ends the march, return uv.

const float PARALLAX_MIN_Z = 0.1;      // the floor of view_ts.z in every division
const int PARALLAX_MAX_LAYERS = 256;  // layers above this count as this many (below 1 as 1)

vec2 parallax_offset(vec2 uv, vec3 view_ts, float scale) {
    return uv;
}

vec2 parallax_steep(vec2 uv, vec3 view_ts, float scale, int layers) {
    return uv;
}

vec2 parallax_occlusion(vec2 uv, vec3 view_ts, float scale, int layers) {
    return uv;
}
