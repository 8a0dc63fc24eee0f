// Correlated multi-jittered sampling keeps its stratification (Kensler
// 2013): one point per 1/N column in y for any N, and where N = m n, one
// per cell of the m x n grid and one per 1/N column in x too.
#include "core/light_sampling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace penumbra {
namespace {

TEST(LightSampling, CorrelatedMultiJitterIsStratified) {
  for (std::uint32_t n : {1u, 2u, 6u, 7u, 16u, 50u, 256u, 1000u}) {
    const auto m = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n)));
    const std::uint32_t rows = (n + m - 1) / m;
    for (std::uint32_t pattern : {0u, 1u, 12345u, 0xdeadbeefu}) {
      std::set<std::uint32_t> cells, columns_x, columns_y;
      for (std::uint32_t s = 0; s < n; ++s) {
        const glm::vec2 p = cmj_sample(s, n, pattern);
        ASSERT_GE(p.x, 0.0f);
        ASSERT_LT(p.x, 1.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LT(p.y, 1.0f);
        const auto cx = static_cast<std::uint32_t>(p.x * m);
        const auto cy = static_cast<std::uint32_t>(p.y * rows);
        cells.insert(cy * m + cx);
        columns_x.insert(static_cast<std::uint32_t>(p.x * n));
        columns_y.insert(static_cast<std::uint32_t>(p.y * n));
      }
      EXPECT_EQ(columns_y.size(), n) << "n " << n << " pattern " << pattern;
      if (m * rows == n) {
        EXPECT_EQ(cells.size(), n) << "n " << n << " pattern " << pattern;
        EXPECT_EQ(columns_x.size(), n) << "n " << n << " pattern " << pattern;
      }
    }
  }
}

// Different patterns give different points (pixels decorrelate), the same
// pattern the same points (references are reproducible), and the mean is
// near the square's centre.
TEST(LightSampling, PatternsAreDeterministicAndDistinct) {
  EXPECT_EQ(cmj_sample(3, 64, 7), cmj_sample(3, 64, 7));
  EXPECT_NE(cmj_sample(3, 64, 7), cmj_sample(3, 64, 8));
  glm::dvec2 mean(0.0);
  for (std::uint32_t s = 0; s < 256; ++s) mean += glm::dvec2(cmj_sample(s, 256, 99));
  mean /= 256.0;
  EXPECT_NEAR(mean.x, 0.5, 0.01);
  EXPECT_NEAR(mean.y, 0.5, 0.01);
}

// A set generated at once holds cmj_sample's very points, bit for bit (so
// the reference sums over the same stratified points however it lists
// them), for counts that fill the m x n grid and counts that do not.
TEST(LightSampling, PointSetHoldsTheSamePointsAsCmjSample) {
  auto key = [](glm::vec2 p) { return std::make_pair(p.x, p.y); };
  CmjPointSet set;
  for (std::uint32_t n : {1u, 2u, 7u, 16u, 50u, 256u, 1000u}) {
    for (std::uint32_t pattern : {0u, 3u, 0xdeadbeefu}) {
      set.generate(n, pattern);
      ASSERT_EQ(set.points().size(), n);
      std::vector<std::pair<float, float>> listed, sampled;
      for (std::uint32_t s = 0; s < n; ++s) {
        listed.push_back(key(set.points()[s]));
        sampled.push_back(key(cmj_sample(s, n, pattern)));
      }
      std::sort(listed.begin(), listed.end());
      std::sort(sampled.begin(), sampled.end());
      EXPECT_EQ(listed, sampled) << "n " << n << " pattern " << pattern;
    }
  }
}

// The cone map is uniform in solid angle: on a 64 x 64 grid of the
// square, every direction is unit and inside the cone, and half of them
// lie inside the inner cone of half the solid angle. On a cone as narrow
// as a 1-degree sun its rim keeps sin(theta_max) to float precision.
TEST(LightSampling, UniformConeIsUniformInSolidAngle) {
  for (float one_minus_cos_max : {0.5f, 0.05f, 3.8e-5f}) {
    const float sin_max = std::sqrt(one_minus_cos_max * (2.0f - one_minus_cos_max));
    int inner = 0, total = 0;
    float widest = 0.0f;
    for (int i = 0; i < 64; ++i) {
      for (int j = 0; j < 64; ++j) {
        const glm::vec3 w =
            uniform_cone(glm::vec2((i + 0.5f) / 64.0f, (j + 0.5f) / 64.0f), one_minus_cos_max);
        EXPECT_NEAR(glm::length(w), 1.0f, 1e-6f);
        const float sin_theta = glm::length(glm::vec2(w));
        EXPECT_LE(sin_theta, sin_max * (1.0f + 1e-5f));
        widest = std::max(widest, sin_theta);
        // 1 - cos(theta) from sin without cancellation.
        const float one_minus_cos = sin_theta * sin_theta / (1.0f + w.z);
        inner += one_minus_cos < 0.5f * one_minus_cos_max;
        ++total;
      }
    }
    EXPECT_NEAR(static_cast<double>(inner) / total, 0.5, 0.02) << one_minus_cos_max;
    EXPECT_NEAR(widest, sin_max, 0.03f * sin_max) << one_minus_cos_max;
  }
}

}  // namespace
}  // namespace penumbra
