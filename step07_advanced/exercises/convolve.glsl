// Image filter, exercise 2 (convolve): one pass of the separable Gaussian blur at pixel p, in GLSL.
// The compute shader filter/shaders/blur_pass.* calls it for every pixel, once with dir = (1, 0)
// (horizontal pass), then on that result with dir = (0, 1)
// (vertical pass). Returns magenta until you write it.
// A wrong or black picture? `python -m step07_advanced.opengl --technique filter --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
// Given by the kernel (see filter/shaders/io.glsl): image_size() (width, height in pixels);
// load_texel(q) (the pixel at q, which must lie inside the image: outside it gives magenta);
// kernel_weight(i) (the normalised weight of tap i).
//   1. Sum kernel_weight(i) * pixel(p + i * dir) over i = -radius..radius
//      (2 radius + 1 taps, radius 0..32).
//   2. Clamp-to-edge: clamp every tap's coordinates to 0..image_size() - 1,
//      per axis (no wrap, no zero padding), so the border pixels are right
//      and no read leaves the image (also for a 1x1 image).
//   3. Use dir as given: the same function does both passes. Return the sum (all four channels).
vec4 blur_pass(ivec2 p, ivec2 dir, int radius) {
    return vec4(1.0, 0.0, 1.0, 1.0);
}
