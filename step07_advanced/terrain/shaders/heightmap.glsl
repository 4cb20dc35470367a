// The terrain's heightmap for the GLSL stages: a 16-bit height split into red (high byte) and green
// (low byte) of an RGBA8 texture, read texel by texel (the exercise's terrain_height interpolates).
uniform sampler2D u_heightmap;

int heightmap_size() {
    return textureSize(u_heightmap, 0).x;
}

float heightmap_texel(ivec2 texel) {
    vec4 t = texelFetch(u_heightmap, texel, 0);
    return (round(t.r * 255.0) * 256.0 + round(t.g * 255.0)) / 65535.0;
}
