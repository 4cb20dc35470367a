// The sky: the scene's cube map (linear RGB, faces +X -X +Y -Y +Z -Z, rows top first) read from a
// storage buffer with bilinear filtering inside each face, the same arithmetic as sky.glsl and
// scene.sample_sky. Needs `sky_texels` and `params` (params.background.w = face size, 0: the
// constant params.background.rgb).
// --8<-- [start:sky]
fn sky_texel(face: u32, row: i32, col: i32, size: i32) -> vec3<f32> {
    return sky_texels[(face * u32(size) + u32(row)) * u32(size) + u32(col)].rgb;
}

fn sky_radiance(d: vec3<f32>) -> vec3<f32> {
    let size = i32(params.background.w);
    if (size == 0) {
        return params.background.rgb;
    }
    let a = abs(d);
    var face: u32;
    var ma: f32;
    var sc: f32;
    var tc: f32;
    if (a.x >= a.y && a.x >= a.z) {
        face = select(1u, 0u, d.x > 0.0); ma = a.x; sc = select(d.z, -d.z, d.x > 0.0); tc = -d.y;
    } else if (a.y >= a.z) {
        face = select(3u, 2u, d.y > 0.0); ma = a.y; sc = d.x; tc = select(-d.z, d.z, d.y > 0.0);
    } else {
        face = select(5u, 4u, d.z > 0.0); ma = a.z; sc = select(-d.x, d.x, d.z > 0.0); tc = -d.y;
    }
    let fx = 0.5 * (sc / ma + 1.0) * f32(size) - 0.5;
    let fy = 0.5 * (tc / ma + 1.0) * f32(size) - 0.5;
    let x0 = clamp(floor(fx), 0.0, f32(size - 1));
    let y0 = clamp(floor(fy), 0.0, f32(size - 1));
    let wx = clamp(fx - x0, 0.0, 1.0);
    let wy = clamp(fy - y0, 0.0, 1.0);
    let c0 = i32(x0);
    let r0 = i32(y0);
    let c1 = min(c0 + 1, size - 1);
    let r1 = min(r0 + 1, size - 1);
    let top = mix(sky_texel(face, r0, c0, size), sky_texel(face, r0, c1, size), wx);
    let bottom = mix(sky_texel(face, r1, c0, size), sky_texel(face, r1, c1, size), wx);
    return mix(top, bottom, wy);
}
// --8<-- [end:sky]
