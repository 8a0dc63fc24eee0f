// Correlated multi-jittered sampling keeps its stratification (Kensler
// 2013): one point per 1/N column in y for any N, and where N = m n, one
// per cell of the m x n grid and one per 1/N column in x too.
#include "reference/light_sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

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

}  // namespace
}  // namespace penumbra
