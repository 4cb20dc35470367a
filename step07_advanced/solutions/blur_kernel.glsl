// Reference solution: the normalised Gaussian weight of one tap (image filter, exercise 1) in GLSL.

float gaussian_weight(int i, int radius) {
    if (radius == 0) {
        return i == 0 ? 1.0 : 0.0;  // the identity kernel (sigma = 0 would divide by zero)
    }
    float sigma = float(radius) / 2.0;
    float k = 1.0 / (2.0 * sigma * sigma);
    float sum = 0.0;  // the sum of the unnormalised taps -radius..radius
    for (int j = -radius; j <= radius; ++j) {
        sum += exp(-float(j * j) * k);
    }
    return exp(-float(i * i) * k) / sum;
}
