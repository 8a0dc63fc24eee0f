// The PNG's bytes come from a table, not from the transfer curve per
// channel: they must be the curve's, rounded, for every float in [0, 1].
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/image.hpp"

namespace penumbra {
namespace {

float srgb_curve(float linear) {
  linear = std::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// Every 61st float from 0 to 1 (about 17 million), each byte's first float
// and the one below it, and values outside [0, 1].
TEST(PngPixels, BytesAreTheCurveRounded) {
  std::vector<float> values;
  const std::uint32_t one = std::bit_cast<std::uint32_t>(1.0f);
  for (std::uint32_t bits = 0; bits <= one; bits += 61)
    values.push_back(std::bit_cast<float>(bits));
  for (int k = 0; k <= 255; ++k) {
    for (float v :
         {(k - 0.5f) / 255.0f, std::pow((k - 0.5f) / 255.0f, 2.4f), (k - 0.5f) / 255.0f / 12.92f}) {
      for (float w = std::nextafter(v, 0.0f), i = 0; i < 3; ++i, w = std::nextafter(w, 1.0f)) {
        values.push_back(w);
      }
    }
  }
  for (float v : {-1.0f, 2.0f, std::numeric_limits<float>::infinity(),
                  std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f}) {
    values.push_back(v);
  }
  Image image(static_cast<int>(values.size()), 1);
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::fill_n(&image.rgba[i * 4], 4, values[i]);
  }
  for (PngEncoding encoding : {PngEncoding::Srgb, PngEncoding::Linear}) {
    const PngPixels pixels = png_pixels(image, encoding);
    ASSERT_EQ(pixels.rgb.size(), values.size() * 3);
    int wrong = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      float v = std::isfinite(values[i]) ? values[i] : 0.0f;
      v = encoding == PngEncoding::Srgb ? srgb_curve(v) : std::clamp(v, 0.0f, 1.0f);
      const auto expected = static_cast<std::uint8_t>(std::lround(v * 255.0f));
      if (pixels.rgb[i * 3] != expected && ++wrong <= 5) {
        ADD_FAILURE() << (encoding == PngEncoding::Srgb ? "sRGB" : "linear") << " value "
                      << values[i] << ": byte " << int(pixels.rgb[i * 3]) << ", expected "
                      << int(expected);
      }
    }
    EXPECT_EQ(wrong, 0);
  }
}

}  // namespace
}  // namespace penumbra
