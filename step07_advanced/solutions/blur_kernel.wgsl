// Reference solution: the normalised Gaussian weight of one tap (image filter, exercise 1) in WGSL.

fn gaussian_weight(i: i32, radius: i32) -> f32 {
    if (radius == 0) {
        return select(0.0, 1.0, i == 0);  // the identity kernel (sigma = 0 would divide by zero)
    }
    let sigma = f32(radius) / 2.0;
    let k = 1.0 / (2.0 * sigma * sigma);
    var sum = 0.0;  // the sum of the unnormalised taps -radius..radius
    for (var j = -radius; j <= radius; j++) {
        sum += exp(-f32(j * j) * k);
    }
    return exp(-f32(i * i) * k) / sum;
}
