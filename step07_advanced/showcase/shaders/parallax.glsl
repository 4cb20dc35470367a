// Tangent frames and parallax occlusion mapping (GLSL).

// The unit tangent T (made orthogonal to n) and bitangent
// B = cross(n, T) · w of the glTF convention.
void tangent_basis(vec3 n, vec4 tangent, out vec3 t, out vec3 b) {
    t = tangent.xyz - n * dot(n, tangent.xyz);
    float len = length(t);
    vec3 axis = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 0.0, 1.0);
    t = len > 1e-6 ? t / len : normalize(axis - n * dot(n, axis));
    b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
}

// Parallax occlusion mapping: march the view ray down through the height field
// (1 = top, 0 = deepest) in tangent space and return the UV where it first goes below the surface,
// refined between the last two layers. v_ts is the unit direction towards the eye in tangent space,
// scale the depth in UV units. Explicit gradients (textureGrad) keep mip selection smooth where the
// shifted UVs jump at the bricks' edges.
// --8<-- [start:march]
vec2 parallax_uv(sampler2D height_map, vec2 uv, vec3 v_ts, float scale, vec2 dx, vec2 dy) {
    if (scale <= 0.0 || v_ts.z <= 0.0) {
        return uv;
    }
    const int MAX_LAYERS = 32;
    // more layers at grazing angles
    float layers = mix(float(MAX_LAYERS), 8.0, clamp(v_ts.z, 0.0, 1.0));
    float layer_depth = 1.0 / layers;
    // +x of tangent space is +u, +y (the bitangent, image up) is -v; a
    // flat view would shift without bound.
    vec2 delta = vec2(v_ts.x, -v_ts.y) / max(v_ts.z, 0.1) * scale / layers;
    vec2 current = uv;
    float depth = 0.0;
    float surface = 1.0 - textureGrad(height_map, current, dx, dy).r;
    for (int i = 0; i < MAX_LAYERS && depth < surface; ++i) {
        current -= delta;
        depth += layer_depth;
        surface = 1.0 - textureGrad(height_map, current, dx, dy).r;
    }
    vec2 previous = current + delta;
    float after = surface - depth;  // <= 0: below the surface
    // >= 0
    float before = 1.0 - textureGrad(height_map, previous, dx, dy).r - (depth - layer_depth);
    float denominator = after - before;
    float w = abs(denominator) > 1e-6 ? after / denominator : 0.0;
    return mix(current, previous, clamp(w, 0.0, 1.0));
}
// --8<-- [end:march]
