// Narkowicz's fit of the ACES filmic curve: linear light in, linear
// light in [0, 1] out (scene.tonemap_np).
vec3 tonemap(vec3 x) {
    x = max(x, vec3(0.0));
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
