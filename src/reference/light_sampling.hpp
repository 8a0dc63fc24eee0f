#pragma once
// Stratified points on the unit square for sampling an area light:
// correlated multi-jittered sampling (Kensler, "Correlated Multi-Jittered
// Sampling", Pixar Technical Memo 13-01, 2013). For any count N, each of
// the N rows of height 1/N holds one point; where N = m n (m =
// floor(sqrt(N)), n = ceil(N / m): a square, or m (m + 1)), each cell of
// the m x n grid and each of the N columns of width 1/N holds one too.
// Each pattern index gives an independent, deterministic set.
#include <cstdint>
#include <glm/glm.hpp>

namespace penumbra {

// Point s (0 <= s < n) of pattern `pattern`'s n points, in [0, 1)^2.
glm::vec2 cmj_sample(std::uint32_t s, std::uint32_t n, std::uint32_t pattern);

}  // namespace penumbra
