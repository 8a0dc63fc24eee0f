// The diverging colour map and the error images built with it.
#include "reference/error_image.hpp"

#include <gtest/gtest.h>

#include "penumbra/error.hpp"

namespace penumbra {
namespace {

// Rec. 709 luma of sRGB-encoded values: enough to order lightness.
float luma(const glm::vec3& c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

void expect_rgb8(const glm::vec3& c, int r, int g, int b, float tolerance) {
  EXPECT_NEAR(c.r * 255.0f, r, tolerance);
  EXPECT_NEAR(c.g * 255.0f, g, tolerance);
  EXPECT_NEAR(c.b * 255.0f, b, tolerance);
}

// Moreland's end points and the grey at the middle (his paper's Table 1
// ends, and the (221, 221, 221) midpoint of its cool-to-warm map).
TEST(DivergingColorMap, EndsAndMiddleAreMorelands) {
  expect_rgb8(diverging_color(-1.0f), 59, 76, 192, 1.0f);
  expect_rgb8(diverging_color(1.0f), 180, 4, 38, 1.0f);
  expect_rgb8(diverging_color(0.0f), 221, 221, 221, 1.5f);
  // Clamped beyond the ends.
  EXPECT_EQ(diverging_color(-7.0f), diverging_color(-1.0f));
  EXPECT_EQ(diverging_color(3.0f), diverging_color(1.0f));
}

// Lightness rises from each end to the middle, so the size of an error
// reads the same on both sides; negative errors are blue, positive red.
TEST(DivergingColorMap, LightnessPeaksAtZeroAndHuesSeparate) {
  float previous = luma(diverging_color(-1.0f));
  for (int i = -19; i <= 0; ++i) {
    const float l = luma(diverging_color(i / 20.0f));
    EXPECT_GT(l, previous) << "t = " << i / 20.0f;
    previous = l;
  }
  for (int i = 1; i <= 20; ++i) {
    const float l = luma(diverging_color(i / 20.0f));
    EXPECT_LT(l, previous) << "t = " << i / 20.0f;
    previous = l;
  }
  for (float t : {-0.9f, -0.5f, -0.1f}) {
    const glm::vec3 c = diverging_color(t);
    EXPECT_GT(c.b, c.r) << t;
  }
  for (float t : {0.1f, 0.5f, 0.9f}) {
    const glm::vec3 c = diverging_color(t);
    EXPECT_GT(c.r, c.b) << t;
  }
}

TEST(ErrorImage, ColoursSignedErrorsAndMarksUncomparedPixels) {
  Image technique(4, 1), reference(4, 1);
  const float t[4] = {0.5f, 1.0f, 0.0f, 0.3f};
  const float r[4] = {0.5f, 0.0f, 1.0f, 0.2f};
  for (int x = 0; x < 4; ++x) {
    technique.pixel(x, 0)[0] = t[x];
    technique.pixel(x, 0)[3] = 1.0f;
    reference.pixel(x, 0)[0] = r[x];
    reference.pixel(x, 0)[3] = x == 3 ? 0.0f : 1.0f;
  }
  const Image e = error_image(technique, reference);
  auto color = [&](int x) {
    return glm::vec3(e.pixel(x, 0)[0], e.pixel(x, 0)[1], e.pixel(x, 0)[2]);
  };
  const float step = 1.0f / 255.0f;
  // Exact: the middle; a leak (too light): the red end; too dark: blue.
  EXPECT_LT(glm::length(color(0) - diverging_color(0.0f)), step);
  EXPECT_LT(glm::length(color(1) - diverging_color(1.0f)), step);
  EXPECT_LT(glm::length(color(2) - diverging_color(-1.0f)), step);
  EXPECT_EQ(color(3), glm::vec3(kErrorImageBackground));
  EXPECT_EQ(e.pixel(0, 0)[3], 1.0f);
  EXPECT_EQ(e.pixel(3, 0)[3], 0.0f);
  // Half the range: the colour a quarter of the way from the middle.
  technique.pixel(0, 0)[0] = 0.5f + 0.5f * kErrorImageRange;
  const Image half = error_image(technique, reference);
  const glm::vec3 c(half.pixel(0, 0)[0], half.pixel(0, 0)[1], half.pixel(0, 0)[2]);
  EXPECT_LT(glm::length(c - diverging_color(0.5f)), step);
  EXPECT_THROW(error_image(Image(2, 2), Image(2, 3)), RuntimeError);
}

}  // namespace
}  // namespace penumbra
