// Tangent frames and parallax occlusion mapping (WGSL).

struct TangentBasis {
    t: vec3<f32>,
    b: vec3<f32>,
};

// The unit tangent T (made orthogonal to n) and bitangent
// B = cross(n, T) · w of the glTF convention.
fn tangent_basis(n: vec3<f32>, tangent: vec4<f32>) -> TangentBasis {
    let raw = tangent.xyz - n * dot(n, tangent.xyz);
    let len = length(raw);
    let axis = select(vec3<f32>(0.0, 0.0, 1.0), vec3<f32>(1.0, 0.0, 0.0), abs(n.x) < 0.9);
    let t = select(normalize(axis - n * dot(n, axis)), raw / max(len, 1e-6), len > 1e-6);
    return TangentBasis(t, cross(n, t) * select(1.0, -1.0, tangent.w < 0.0));
}

// Parallax occlusion mapping: march the view ray down through the height field
// (1 = top, 0 = deepest) in tangent space and return the UV where it first goes below the surface,
// refined between the last two layers. v_ts is the unit direction towards the eye in tangent space,
// scale the depth in UV units. Explicit gradients (textureSampleGrad) are also what WGSL requires
// for sampling inside non-uniform loops.
// --8<-- [start:march]
fn parallax_uv(height_map: texture_2d<f32>, height_sampler: sampler, uv: vec2<f32>, v_ts: vec3<f32>,
               scale: f32, dx: vec2<f32>, dy: vec2<f32>) -> vec2<f32> {
    if (scale <= 0.0 || v_ts.z <= 0.0) {
        return uv;
    }
    let max_layers = 32;
    // more layers at grazing angles
    let layers = mix(f32(max_layers), 8.0, clamp(v_ts.z, 0.0, 1.0));
    let layer_depth = 1.0 / layers;
    // +x of tangent space is +u, +y (the bitangent, image up) is -v; a
    // flat view would shift without bound.
    let delta = vec2<f32>(v_ts.x, -v_ts.y) / max(v_ts.z, 0.1) * scale / layers;
    var current = uv;
    var depth = 0.0;
    var surface = 1.0 - textureSampleGrad(height_map, height_sampler, current, dx, dy).r;
    for (var i = 0; i < max_layers && depth < surface; i++) {
        current -= delta;
        depth += layer_depth;
        surface = 1.0 - textureSampleGrad(height_map, height_sampler, current, dx, dy).r;
    }
    let previous = current + delta;
    let after = surface - depth;  // <= 0: below the surface
    let before = 1.0 - textureSampleGrad(height_map, height_sampler, previous, dx, dy).r
        - (depth - layer_depth);
    let denominator = after - before;
    let w = select(0.0, after / denominator, abs(denominator) > 1e-6);
    return mix(current, previous, clamp(w, 0.0, 1.0));
}
// --8<-- [end:march]
