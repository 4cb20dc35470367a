// Image filter, exercise 1 (blur_kernel): the normalised Gaussian weight of tap i in WGSL, for a
// kernel of the given radius. The compute shader filter/shaders/weights.* calls it once per tap to
// fill the weight table the blur kernels read. Returns 0 until you write it
// (every blurred pixel is then black).
// A wrong or black picture? `python -m step07_advanced.webgpu --technique filter --student --editor`:
// View > Shader shows a compile error at its line and rebuilds on save; View > Frame inspector shows
// each draw's uniforms by name and which draw wrote a pixel (step 07's page: "Find a black-screen bug").
//
//   radius: 0..32; i: the tap, -radius <= i <= radius.
//   1. sigma = radius / 2 (as a float), and the unnormalised weight g(i) = exp(-i^2 / (2 sigma^2)).
//   2. Normalise: divide by the sum of g(j) over ALL taps j = -radius..radius, so the 2 radius + 1
//      weights sum to 1 (a constant image stays constant).
//   3. radius 0 is the identity: weight 1 for i = 0
//      (careful: sigma = 0 there, so no division by it).
//   The table must be symmetric (weight(-i) = weight(i)) and hold no NaN or Inf.
fn gaussian_weight(i: i32, radius: i32) -> f32 {
    return 0.0;
}
