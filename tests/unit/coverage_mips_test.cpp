// The coverage-preserving mip chain of alpha-tested textures
// (scene/coverage_mips.hpp): level sizes as OpenGL's, colour averaged in
// linear light, and every level's fraction of texels at or above the
// cutoff equal to level 0's, where a plain box filter thins it out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "scene/coverage_mips.hpp"

namespace penumbra {
namespace {

// Sparse leaves: 1-texel-wide solid diagonals every third texel and a
// few 3 x 3 blocks; about a third of the texels are solid.
TextureImage sparse_leaves(int side) {
  TextureImage image;
  image.name = "leaves";
  image.width = image.height = side;
  image.rgba.assign(4 * static_cast<std::size_t>(side) * side, 0);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const bool solid = (x + y) % 3 == 0 || (x % 16 < 3 && y % 16 < 3);
      std::uint8_t* p = &image.rgba[4 * (static_cast<std::size_t>(y) * side + x)];
      p[0] = 50;
      p[1] = 170;
      p[2] = 30;
      p[3] = solid ? 255 : 0;
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
  EXPECT_NEAR(level0, 0.37, 0.03);
  for (std::size_t k = 1; k < kept.size(); ++k) {
    const double texels = static_cast<double>(kept[k].width) * kept[k].height;
    const double c = alpha_coverage(kept[k], 0.5f);
    std::printf("level %zu: coverage %.3f kept, %.3f box-filtered\n", k, c,
                alpha_coverage(plain[k], 0.5f));
    // To the nearest texel of the level (ties in alpha may add a few).
    EXPECT_NEAR(c, level0, 0.5 / texels + 0.01) << k;
  }
  // The box filter alone loses the diagonals from level 1 on.
  EXPECT_LT(alpha_coverage(plain[2], 0.5f), 0.5 * level0);
}

TEST(CoverageMips, KeepsCoverageAtAnyCutoff) {
  const TextureImage image = sparse_leaves(32);
  for (const float cutoff : {0.1f, 0.33f, 0.8f, 1.0f}) {
    const std::vector<MipLevel> chain = coverage_mip_chain(image, cutoff);
    const double level0 = alpha_coverage(chain[0], cutoff);
    for (std::size_t k = 1; k + 2 < chain.size(); ++k) {
      const double texels = static_cast<double>(chain[k].width) * chain[k].height;
      EXPECT_NEAR(alpha_coverage(chain[k], cutoff), level0, 0.5 / texels + 0.02)
          << cutoff << " level " << k;
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
  m.alpha = 0.3f;  // every texel a hole: nothing to keep
  EXPECT_LT(texture_alpha_cutoff(m), 0.0f);
}

}  // namespace
}  // namespace penumbra
