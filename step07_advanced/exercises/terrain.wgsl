// Terrain exercises in WGSL: the level of detail of a patch edge, and the heightfield's height and
// normal. Included by the terrain's compute pass and render shader (WebGPU) and by the tests'
// harness. Until you write them the stubs return the minimum level, height 0 and the up vector: the
// terrain renders flat and coarse, and `pytest --student tests/step07_advanced -k terrain` fails.
// Keep every function free of NaN for any input.
// A wrong or black picture? `python -m step07_advanced.webgpu --technique terrain --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// The including shader provides the heightmap, a square map of N x N texels:
//   fn heightmap_size() -> i32                       // N
//   fn heightmap_texel(texel: vec2<i32>) -> f32      // the height in [0, 1] of texel
//                                                    // (column, row), 0 <= both < N only

// --8<-- [start:tess_level]
// The tessellation level of the patch edge from a to b (world space) seen from the camera at eye.
// lod = (scale, min_level, max_level):  level = clamp(scale * |b - a| / d, min_level, max_level)
// with d = the distance from eye to the edge's midpoint (a + b) / 2: near edges get more segments.
// When d < 1e-6 (the camera on the midpoint) the level is max_level. Never NaN;
// tess_level(a, b) == tess_level(b, a).
fn tess_level(a: vec3<f32>, b: vec3<f32>, eye: vec3<f32>, lod: vec3<f32>) -> f32 {
    return lod.y;  // the minimum level: replace with the rule above
}
// --8<-- [end:tess_level]

// --8<-- [start:terrain_height]
// The height in [0, 1] at uv (u, v in [0, 1]) by bilinear interpolation of the texels, whose
// centres lie at uv = (texel + 0.5) / N (u picks the column, v the row). Clamp addressing: texel
// indices outside [0, N - 1] read the nearest edge texel (never call heightmap_texel out of range),
// so any uv (also < 0 or > 1) gives a value.
fn terrain_height(uv: vec2<f32>) -> f32 {
    return 0.0;  // flat: replace with the bilinear, clamped lookup above
}
// --8<-- [end:terrain_height]

// --8<-- [start:terrain_normal]
// The unit normal of the terrain y = height_scale * terrain_height(uv) over
// the square of side size in x and z (world x grows with u, world z with v),
// by central differences one texel (e = 1 / N) apart:
//   dh/du = (terrain_height(uv + (e, 0)) - terrain_height(uv - (e, 0))) / (2 e), dh/dv likewise,
//   normal = normalize(-height_scale / size * dh/du, 1, -height_scale / size * dh/dv).
// scale = (size, height_scale). A flat map gives exactly (0, 1, 0).
fn terrain_normal(uv: vec2<f32>, scale: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(0.0, 1.0, 0.0);  // straight up: replace with the central differences above
}
// --8<-- [end:terrain_normal]
