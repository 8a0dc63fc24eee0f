// Correlated multi-jittered sampling keeps its stratification (Kensler
// 2013): one point per 1/N column in y for any N, and where N = m n, one
// per cell of the m x n grid and one per 1/N column in x too; the
// equal-area cells of square_cell hold one sample each for any N.
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

// The cells of square_cell partition the square for every count: each
// has area 1/n and lies inside the square, and every point of a fine grid
// over the square lies in exactly one of them (no gap, no overlap). The
// cells stay near square.
TEST(LightSampling, SquareCellsPartitionTheSquareForAnyCount) {
  std::vector<std::uint32_t> counts;
  for (std::uint32_t n = 1; n <= 80; ++n) counts.push_back(n);
  for (std::uint32_t n : {127u, 128u, 255u, 1000u}) counts.push_back(n);
  constexpr int kGrid = 97;  // points off the cells' edges
  for (std::uint32_t n : counts) {
    std::vector<SquareCell> cells;
    for (std::uint32_t i = 0; i < n; ++i) {
      const SquareCell c = square_cell(i, n);
      EXPECT_NEAR(c.size.x * c.size.y, 1.0f / static_cast<float>(n), 1e-6f) << n << " " << i;
      EXPECT_GE(c.origin.x, 0.0f);
      EXPECT_GE(c.origin.y, 0.0f);
      EXPECT_LE(c.origin.x + c.size.x, 1.0f + 1e-6f);
      EXPECT_LE(c.origin.y + c.size.y, 1.0f + 1e-6f);
      EXPECT_LT(c.row, c.rows);
      EXPECT_LT(c.column, c.columns);
      const float aspect = c.size.x / c.size.y;
      EXPECT_LE(std::max(aspect, 1.0f / aspect), 3.0f) << n << " " << i;
      cells.push_back(c);
    }
    for (int gx = 0; gx < kGrid; ++gx) {
      for (int gy = 0; gy < kGrid; ++gy) {
        const glm::vec2 p((gx + 0.37f) / kGrid, (gy + 0.61f) / kGrid);
        int holding = 0;
        for (const SquareCell& c : cells) {
          holding += p.x >= c.origin.x && p.x < c.origin.x + c.size.x && p.y >= c.origin.y &&
                     p.y < c.origin.y + c.size.y;
        }
        ASSERT_EQ(holding, 1) << "n " << n << " point " << p.x << ", " << p.y;
      }
    }
  }
}

// The n stratified samples of a pattern visit every cell of the partition
// once whatever n is (where Kensler's cmj_sample points leave cells of its
// m x ceil(n/m) grid empty: n = 10 fills 5 of 6 columns' worth), each
// point lies in its cell, and the points' x coordinates fill the n columns
// of width 1/n once.
TEST(LightSampling, StratifiedSamplesVisitEveryCellOnce) {
  for (std::uint32_t n : {1u, 2u, 3u, 5u, 9u, 10u, 12u, 16u, 30u, 32u, 35u, 64u, 99u, 1000u}) {
    for (std::uint32_t pattern : {0u, 7u, 0xdeadbeefu}) {
      std::set<std::pair<float, float>> cells;
      std::set<std::uint32_t> columns_x;
      for (std::uint32_t k = 0; k < n; ++k) {
        const CellSample s = stratified_sample(k, n, pattern);
        cells.insert({s.cell.origin.x, s.cell.origin.y});
        const glm::vec2 lo = s.cell.origin - 1e-6f, hi = s.cell.origin + s.cell.size + 1e-6f;
        EXPECT_TRUE(s.point.x >= lo.x && s.point.x <= hi.x && s.point.y >= lo.y &&
                    s.point.y <= hi.y)
            << "n " << n << " k " << k;
        EXPECT_LT(s.point.x, 1.0f);
        EXPECT_LT(s.point.y, 1.0f);
        columns_x.insert(static_cast<std::uint32_t>(s.point.x * static_cast<float>(n)));
      }
      EXPECT_EQ(cells.size(), n) << "n " << n << " pattern " << pattern;
      EXPECT_EQ(columns_x.size(), n) << "n " << n << " pattern " << pattern;
    }
  }
  EXPECT_NE(stratified_sample(0, 16, 0).point, stratified_sample(0, 16, 1).point);
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
