#include "render/ssao_kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace penumbra {
namespace {

TEST(SsaoKernel, RadicalInverseMirrorsTheDigits) {
  EXPECT_DOUBLE_EQ(radical_inverse(2, 0), 0.0);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 1), 0.5);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 3), 0.75);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 6), 0.375);  // 110 -> 0.011
  EXPECT_DOUBLE_EQ(radical_inverse(3, 1), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 5), 2.0 / 3.0 + 1.0 / 9.0);  // 12 -> 0.21
}

// Unit directions in the open upper hemisphere, distances in (0, 1), and
// cos theta stratified: its mean is exactly 1/2, the mean of cos theta over
// directions uniform in solid angle.
TEST(SsaoKernel, UnitDirectionsInTheHemisphere) {
  for (int k : {1, 2, 7, 16, 64}) {
    std::vector<glm::vec4> kernel = ssao_kernel(k);
    ASSERT_EQ(static_cast<int>(kernel.size()), k);
    double mean_z = 0.0;
    for (const glm::vec4& s : kernel) {
      EXPECT_NEAR(glm::length(glm::vec3(s)), 1.0f, 1e-6f);
      EXPECT_GT(s.z, 0.0f);
      EXPECT_LT(s.z, 1.0f);
      EXPECT_GT(s.w, 0.0f);
      EXPECT_LT(s.w, 1.0f);
      mean_z += s.z / k;
    }
    EXPECT_NEAR(mean_z, 0.5, 1e-6) << k;
  }
}

// The estimator of seed 003, sum of cos over the visible samples / sum of
// cos, for occluders whose cosine-weighted visibility is known: a cone of
// directions around the normal left open (visibility 1 - c^2 for
// cos theta > c), and a wall through the point (visibility 1/2), the latter
// averaged over the per-pixel rotations the shader applies.
TEST(SsaoKernel, EstimatesCosineWeightedVisibility) {
  for (int k : {8, 16, 64}) {
    std::vector<glm::vec4> kernel = ssao_kernel(k);
    double total = 0.0;
    for (const glm::vec4& s : kernel) total += s.z;
    for (double c : {0.3, 0.5, 0.8}) {
      double visible = 0.0;
      for (const glm::vec4& s : kernel) visible += s.z > c ? s.z : 0.0;
      EXPECT_NEAR(visible / total, 1.0 - c * c, 1.0 / k) << "k " << k << ", cone " << c;
    }
    double worst = 0.0, mean = 0.0;
    const int rotations = 360;
    for (int r = 0; r < rotations; ++r) {
      const double angle = 2.0 * std::numbers::pi * r / rotations;
      double visible = 0.0;
      for (const glm::vec4& s : kernel) {
        const double x = std::cos(angle) * s.x - std::sin(angle) * s.y;
        visible += x > 0.0 ? s.z : 0.0;
      }
      worst = std::max(worst, std::abs(visible / total - 0.5));
      mean += visible / total / rotations;
    }
    std::printf(
        "k = %d: wall through the point, estimate 0.5 +- %.3f (worst rotation), mean %.4f\n", k,
        worst, mean);
    EXPECT_NEAR(mean, 0.5, 1e-3) << k;
    EXPECT_LT(worst, 0.6 / k) << k;  // low discrepancy: O(1/k), not O(1/sqrt(k))
  }
}

}  // namespace
}  // namespace penumbra
