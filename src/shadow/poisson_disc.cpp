#include "penumbra/shadow/poisson_disc.hpp"

#include <cstdint>
#include <limits>

namespace penumbra {

namespace {

// A small fixed generator (splitmix64): std::uniform_real_distribution's
// output is not specified across standard libraries.
struct SplitMix64 {
  std::uint64_t state;
  float next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<float>(z >> 40) / static_cast<float>(1ull << 24);  // [0, 1)
  }
};

}  // namespace

std::vector<glm::vec2> poisson_square_samples(int count) {
  SplitMix64 rng{0x70656e756d627261ull};  // "penumbra"
  std::vector<glm::vec2> points;
  points.reserve(static_cast<std::size_t>(count));
  constexpr int kCandidatesPerPoint = 16;
  for (int n = 0; n < count; ++n) {
    glm::vec2 best{0.0f};
    float best_distance = -1.0f;
    // The first sample is the centre, so one sample is the plain test.
    const int candidates = n == 0 ? 0 : kCandidatesPerPoint * n;
    for (int c = 0; c < candidates; ++c) {
      glm::vec2 candidate{2.0f * rng.next() - 1.0f, 2.0f * rng.next() - 1.0f};
      float nearest = std::numeric_limits<float>::max();
      for (const glm::vec2& p : points) {
        const glm::vec2 d = candidate - p;
        nearest = std::min(nearest, glm::dot(d, d));
      }
      if (nearest > best_distance) {
        best_distance = nearest;
        best = candidate;
      }
    }
    points.push_back(best);
  }
  return points;
}

}  // namespace penumbra
