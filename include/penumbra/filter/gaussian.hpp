#pragma once
// Weights of the separable Gaussian blur of the filterable shadow maps.
#include <vector>

namespace penumbra {

// The 2w + 1 weights beta * exp(-i^2 / (2 s^2)) for i = -w..w, with
// s = w / 2 and beta chosen so that they sum to 1. w = 0 gives {1};
// negative w is treated as 0.
std::vector<float> gaussian_weights(int w);

}  // namespace penumbra
