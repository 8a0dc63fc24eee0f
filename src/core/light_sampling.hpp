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
#include <vector>

namespace penumbra {

// Point s (0 <= s < n) of pattern `pattern`'s n points, in [0, 1)^2.
glm::vec2 cmj_sample(std::uint32_t s, std::uint32_t n, std::uint32_t pattern);

// All n points of a pattern at once, for an estimator that sums over all
// of them: the very points cmj_sample gives for s = 0 .. n-1, bit for bit,
// listed stratum by stratum instead of in cmj_sample's shuffled order.
// Listing every stratum makes Kensler's first permutation (which only
// reorders the strata) unnecessary, and his column and row permutations
// are computed once per set (sqrt(n) each) instead of for every point:
// each point then costs two hashes. Reusable: keeps its buffers.
class CmjPointSet {
 public:
  // Fills points() with pattern `pattern`'s n points (n >= 1).
  void generate(std::uint32_t n, std::uint32_t pattern);
  [[nodiscard]] const std::vector<glm::vec2>& points() const { return points_; }

 private:
  std::vector<std::uint32_t> column_, row_;  // the permuted strata
  std::vector<glm::vec2> points_;
};

// A point of the unit disk from a point of the unit square, area-uniform
// and keeping strata apart (Shirley & Chiu, "A Low Distortion Map Between
// Disk and Square", JGT 1997: concentric squares to concentric circles).
glm::vec2 concentric_disk(glm::vec2 u);

// A unit direction uniform in solid angle over the cone of directions
// within angle theta_max of +z, from a point of the unit square; the cone
// is given by 1 - cos(theta_max) (accurate for small cones, where cos is
// 1 to float precision). The disk's area maps to the cone's solid angle in
// proportion (1 - cos(theta) = r^2 (1 - cos(theta_max)); pbrt-v4,
// SampleUniformCone, through the concentric disk), so the square's strata
// stay strata of the cone.
glm::vec3 uniform_cone(glm::vec2 u, float one_minus_cos_max);

// The same from the point d = concentric_disk(u) of the unit disk.
glm::vec3 uniform_cone_from_disk(glm::vec2 d, float one_minus_cos_max);

}  // namespace penumbra
