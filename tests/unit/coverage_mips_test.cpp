// The coverage-preserving mip chain of alpha-tested textures
// (scene/coverage_mips.hpp): level sizes as OpenGL's, colour averaged in
// linear light, and every level's fraction at or above the cutoff, as a
// bilinear filter reads it, equal to level 0's, where a plain box filter
// thins it out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "scene/coverage_mips.hpp"

namespace penumbra {
namespace {

// Sparse leaves: discs of radius 1.6 texels at pseudo-random centres
// (repeating at the edges), about a third of the texels solid.
TextureImage sparse_leaves(int side) {
  TextureImage image;
  image.name = "leaves";
  image.width = image.height = side;
  image.rgba.assign(4 * static_cast<std::size_t>(side) * side, 0);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = 50;
    image.rgba[i + 1] = 170;
    image.rgba[i + 2] = 30;
  }
  std::uint32_t state = 7u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  const int leaves = side * side / 20;
  for (int leaf = 0; leaf < leaves; ++leaf) {
    const float cx = next() * side, cy = next() * side;
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        const int x = static_cast<int>(std::floor(cx)) + dx;
        const int y = static_cast<int>(std::floor(cy)) + dy;
        const float ox = x + 0.5f - cx, oy = y + 0.5f - cy;
        if (ox * ox + oy * oy > 1.6f * 1.6f) continue;
        image.rgba[4 * (static_cast<std::size_t>((y + side) % side) * side + (x + side) % side) +
                   3] = 255;
      }
    }
  }
  return image;
}

TEST(CoverageMips, EveryLevelKeepsLevelZerosCoverage) {
  const TextureImage image = sparse_leaves(64);
  const std::vector<MipLevel> kept = coverage_mip_chain(image, 0.5f);
  const std::vector<MipLevel> plain = coverage_mip_chain(image, -1.0f);
  ASSERT_EQ(kept.size(), 7u);
  const double level0 = alpha_coverage(kept[0], 0.5f);
  EXPECT_NEAR(level0, 0.33, 0.08);
  for (std::size_t k = 1; k < kept.size(); ++k) {
    const double c = alpha_coverage(kept[k], 0.5f);
    std::printf("level %zu: coverage %.3f kept, %.3f box-filtered\n", k, c,
                alpha_coverage(plain[k], 0.5f));
    // Down to 8 x 8 texels, where a texel is 1.5% of the level.
    if (kept[k].width >= 8) {
      EXPECT_NEAR(c, level0, 0.02) << k;
    }
  }
  // The box filter alone loses most leaves from level 3 on.
  EXPECT_LT(alpha_coverage(plain[3], 0.5f), 0.25 * level0);
}

TEST(CoverageMips, KeepsCoverageAtAnyCutoff) {
  const TextureImage image = sparse_leaves(32);
  for (const float cutoff : {0.1f, 0.33f, 0.8f}) {
    const std::vector<MipLevel> chain = coverage_mip_chain(image, cutoff);
    const double level0 = alpha_coverage(chain[0], cutoff);
    for (std::size_t k = 1; chain[k].width >= 8; ++k) {
      EXPECT_NEAR(alpha_coverage(chain[k], cutoff), level0, 0.02) << cutoff << " level " << k;
    }
  }
}

TEST(CoverageMips, LevelSizesAreOpenGlsAndColourIsAveragedInLinearLight) {
  TextureImage image;
  image.width = 5;
  image.height = 3;
  // Alternating black and white columns, opaque.
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const std::uint8_t c = x % 2 == 0 ? 0 : 255;
      image.rgba.insert(image.rgba.end(), {c, c, c, 255});
    }
  }
  const std::vector<MipLevel> chain = coverage_mip_chain(image, 0.5f);
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[1].width, 2);
  EXPECT_EQ(chain[1].height, 1);
  EXPECT_EQ(chain[2].width, 1);
  EXPECT_EQ(chain[2].height, 1);
  // Texel 0 of level 1 averages one black and one white column: linear 0.5
  // is sRGB byte 188, not 128.
  EXPECT_NEAR(chain[1].rgba[0], 188, 1);
  EXPECT_EQ(chain[1].rgba[3], 255);
  EXPECT_EQ(chain[2].rgba[3], 255);
}

TEST(CoverageMips, TextureCutoffIsTheMaterialsOverItsAlphaFactor) {
  Material m;
  EXPECT_LT(texture_alpha_cutoff(m), 0.0f);  // opaque
  m.alpha_mode = AlphaMode::Mask;
  m.alpha_cutoff = 0.4f;
  m.alpha = 0.8f;
  EXPECT_FLOAT_EQ(texture_alpha_cutoff(m), 0.5f);
  m.alpha_mode = AlphaMode::Blend;  // tested at 0.5
  EXPECT_FLOAT_EQ(texture_alpha_cutoff(m), 0.625f);
  m.alpha = 0.5f;  // only opaque texels pass: nothing to keep
  EXPECT_LT(texture_alpha_cutoff(m), 0.0f);
  m.alpha = 0.3f;  // every texel a hole
  EXPECT_LT(texture_alpha_cutoff(m), 0.0f);
}

}  // namespace
}  // namespace penumbra
