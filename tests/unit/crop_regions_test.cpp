// The report's zoom regions land where their rules say: on the technique's
// error, on a sharp shadow edge, on a wide soft one; the crop repeats each
// pixel scale x scale.
#include "report/crop_regions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "penumbra/error.hpp"

namespace {

using penumbra::CropRegion;
using penumbra::Image;

Image filled(int w, int h, float value) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = value;
      p[3] = 1.0f;
    }
  }
  return image;
}

bool contains(const CropRegion& r, int x, int y) {
  return x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
}

TEST(CropRegions, EachRuleFindsItsFeature) {
  constexpr int w = 120, h = 60;
  // Reference: lit, with a hard edge (0 | 1) at x = 20, and in rows 30..59
  // a soft dip down to 0.2 and back over x = 70..110.
  Image reference = filled(w, h, 1.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < 20; ++x) reference.pixel(x, y)[0] = 0.0f;
  }
  for (int y = 30; y < h; ++y) {
    for (int x = 70; x <= 110; ++x) {
      reference.pixel(x, y)[0] = 1.0f - 0.8f * (1.0f - std::abs(x - 90) / 20.0f);
    }
  }
  // The technique: the reference, wrong by 0.5 in a block at (40..49, 5..14).
  Image technique = reference;
  for (int y = 5; y < 15; ++y) {
    for (int x = 40; x < 50; ++x) technique.pixel(x, y)[0] -= 0.5f;
  }
  // The background (alpha 0) beside the block is no edge.
  for (int y = 0; y < h; ++y) reference.pixel(w - 1, y)[3] = 0.0f;

  const auto regions = penumbra::choose_crop_regions(reference, {&technique}, 12, 12);
  ASSERT_EQ(regions.size(), 3u);
  EXPECT_EQ(regions[0].id, "largest-error");
  EXPECT_TRUE(contains(regions[0], 45, 10)) << regions[0].x << "," << regions[0].y;
  EXPECT_NEAR(regions[0].score, 0.5 * 100, 1e-3);
  EXPECT_EQ(regions[1].id, "contact-shadow");
  EXPECT_TRUE(contains(regions[1], 19, 10) && contains(regions[1], 20, 10))
      << regions[1].x << "," << regions[1].y;
  EXPECT_EQ(regions[2].id, "wide-penumbra");
  EXPECT_GE(regions[2].x, 70);
  EXPECT_LE(regions[2].x + regions[2].width, 110);
  EXPECT_GE(regions[2].y, 30);
  for (const CropRegion& r : regions) {
    EXPECT_EQ(r.width, 12);
    EXPECT_EQ(r.height, 12);
  }
}

TEST(CropRegions, LaterRegionsDoNotOverlapEarlierOnes) {
  // The error sits on the only sharp edge: the contact region must move off it.
  Image reference = filled(64, 32, 1.0f);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) reference.pixel(x, y)[0] = 0.0f;
  }
  Image technique = reference;
  for (int y = 0; y < 32; ++y) technique.pixel(31, y)[0] = 0.6f;
  const auto r = penumbra::choose_crop_regions(reference, {&technique}, 8, 8);
  for (std::size_t i = 0; i < r.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const bool apart = r[i].x >= r[j].x + r[j].width || r[j].x >= r[i].x + r[i].width ||
                         r[i].y >= r[j].y + r[j].height || r[j].y >= r[i].y + r[i].height;
      EXPECT_TRUE(apart) << i << " overlaps " << j;
    }
  }
}

TEST(CropRegions, CropRepeatsEachPixel) {
  Image image(4, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) image.pixel(x, y)[0] = static_cast<float>(10 * y + x);
  }
  const CropRegion region{"r", "r", "", 1, 1, 2, 2, 0.0};
  const Image crop = penumbra::crop_nearest(image, region, 4);
  ASSERT_EQ(crop.width, 8);
  ASSERT_EQ(crop.height, 8);
  EXPECT_EQ(crop.pixel(0, 0)[0], 11.0f);
  EXPECT_EQ(crop.pixel(3, 3)[0], 11.0f);
  EXPECT_EQ(crop.pixel(4, 3)[0], 12.0f);
  EXPECT_EQ(crop.pixel(7, 7)[0], 22.0f);
  EXPECT_THROW(penumbra::crop_nearest(image, {"r", "r", "", 3, 0, 2, 2, 0.0}, 4),
               penumbra::RuntimeError);
}

}  // namespace
