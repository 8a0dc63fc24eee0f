// The shadow metrics on image pairs whose answers are known by hand.
#include "reference/shadow_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "penumbra/error.hpp"

namespace penumbra {
namespace {

// A w x h shadow image of constant value, every pixel geometry.
Image constant(int w, int h, float value) {
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

void set(Image& image, int x, int y, float value) {
  float* p = image.pixel(x, y);
  p[0] = p[1] = p[2] = value;
}

TEST(ShadowMetrics, IdenticalImagesHaveNoError) {
  Image reference = constant(8, 4, 1.0f);
  for (int x = 0; x < 4; ++x) set(reference, x, 1, 0.0f);
  set(reference, 5, 2, 0.37f);
  const ShadowMetrics m = compare_shadow(reference, reference);
  EXPECT_EQ(m.pixels, 32);
  EXPECT_EQ(m.mean_absolute_error, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.max_error, 0.0);
  EXPECT_EQ(m.leak_fraction, 0.0);
  EXPECT_EQ(m.over_dark_fraction, 0.0);
}

// A shadow of 4 pixels the technique lights up: 3 leak (reference < 0.1,
// technique > 0.3); one at 0.25 is an error but not a leak.
TEST(ShadowMetrics, HandBuiltLeakIsCounted) {
  Image reference = constant(10, 10, 1.0f);
  Image technique = constant(10, 10, 1.0f);
  for (int x = 0; x < 4; ++x) set(reference, x, 0, 0.0f);
  set(technique, 0, 0, 1.0f);
  set(technique, 1, 0, 0.5f);
  set(technique, 2, 0, 0.31f);
  set(technique, 3, 0, 0.25f);
  const ShadowMetrics m = compare_shadow(technique, reference);
  EXPECT_EQ(m.pixels, 100);
  EXPECT_DOUBLE_EQ(m.leak_fraction, 0.03);
  EXPECT_EQ(m.over_dark_fraction, 0.0);
  const double sum = 1.0 + 0.5 + double(0.31f) + 0.25;
  EXPECT_NEAR(m.mean_absolute_error, sum / 100.0, 1e-7);
  EXPECT_NEAR(m.rmse, std::sqrt((1.0 + 0.25 + 0.31 * 0.31 + 0.0625) / 100.0), 1e-6);
  EXPECT_DOUBLE_EQ(m.max_error, 1.0);
}

// The mirror case: lit pixels the technique darkens below 0.7.
TEST(ShadowMetrics, HandBuiltOverDarkeningIsCounted) {
  const Image reference = constant(5, 4, 0.95f);
  Image technique = constant(5, 4, 0.95f);
  set(technique, 2, 2, 0.0f);
  set(technique, 3, 2, 0.69f);
  set(technique, 4, 2, 0.71f);  // darker, but not over-dark
  const ShadowMetrics m = compare_shadow(technique, reference);
  EXPECT_DOUBLE_EQ(m.over_dark_fraction, 2.0 / 20.0);
  EXPECT_EQ(m.leak_fraction, 0.0);
  EXPECT_NEAR(m.max_error, 0.95, 1e-6);
}

// Pixels without geometry (alpha 0) in either image are not compared.
TEST(ShadowMetrics, BackgroundIsNotCompared) {
  Image reference = constant(4, 4, 0.0f);
  Image technique = constant(4, 4, 1.0f);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      if (x < 2) reference.pixel(x, y)[3] = 0.0f;
      if (y < 2) technique.pixel(x, y)[3] = 0.0f;
    }
  }
  const ShadowMetrics m = compare_shadow(technique, reference);
  EXPECT_EQ(m.pixels, 4);
  EXPECT_DOUBLE_EQ(m.leak_fraction, 1.0);
  EXPECT_DOUBLE_EQ(m.mean_absolute_error, 1.0);
  const ShadowMetrics none = compare_shadow(constant(2, 2, 1.0f), Image(2, 2));
  EXPECT_EQ(none.pixels, 0);
  EXPECT_EQ(none.mean_absolute_error, 0.0);
}

TEST(ShadowMetrics, SizesMustMatch) {
  EXPECT_THROW(compare_shadow(constant(4, 4, 1.0f), constant(4, 3, 1.0f)), RuntimeError);
}

}  // namespace
}  // namespace penumbra
