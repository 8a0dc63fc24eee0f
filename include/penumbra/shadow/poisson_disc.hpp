#pragma once
// The fixed sample set of PCF and PCSS: points in the square [-1, 1]^2
// chosen by Mitchell's best-candidate algorithm (Mitchell 1991), so that
// every prefix of the sequence is itself well spread (a Poisson-disc-like
// set): PCF with n samples uses the first n.
#include <glm/glm.hpp>
#include <vector>

namespace penumbra {

inline constexpr int kPoissonSampleCount = 64;

// Deterministic: the same points on every run and machine.
std::vector<glm::vec2> poisson_square_samples(int count = kPoissonSampleCount);

}  // namespace penumbra
