#pragma once
// Weights of the separable Gaussian blur of the filterable shadow maps.
#include <string>
#include <vector>

namespace penumbra {

// The 2w + 1 weights beta * exp(-i^2 / (2 s^2)) for i = -w..w, with
// s = w / 2 and beta chosen so that they sum to 1. w = 0 gives {1};
// negative w is treated as 0.
std::vector<float> gaussian_weights(int w);

// The same weights as a GLSL initializer list ("0.1, 0.2, ..."), each with 9
// significant digits, which is the float itself: the blur shaders take them
// as compile-time constants (GAUSSIAN_WEIGHTS), which llvmpipe runs about
// three times faster than weights read from a buffer per tap.
std::string gaussian_weight_list(int w);

}  // namespace penumbra
