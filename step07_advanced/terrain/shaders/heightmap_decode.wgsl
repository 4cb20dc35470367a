// The 16-bit height of a texel: red holds the high byte, green the
// low byte (heightfield.py encodes them). The including file declares
// `heightmap: texture_2d<f32>` in its own bind group.
fn heightmap_size() -> i32 {
    return i32(textureDimensions(heightmap).x);
}

fn heightmap_texel(texel: vec2<i32>) -> f32 {
    let t = textureLoad(heightmap, texel, 0);
    return (round(t.r * 255.0) * 256.0 + round(t.g * 255.0)) / 65535.0;
}
