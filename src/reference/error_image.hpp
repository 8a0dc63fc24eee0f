#pragma once
// Pictures of a technique's error: the signed difference technique -
// reference through a diverging colour map, blue where the technique is too
// dark, red where it lets too much light through (leaks), near-white where
// it is right.
#include <glm/glm.hpp>

#include "io/image.hpp"

namespace penumbra {

// Moreland's "cool to warm" diverging map (K. Moreland, "Diverging Color
// Maps for Scientific Visualization", ISVC 2009): t = -1 is blue (59, 76,
// 192), t = 0 a neutral grey (221, 221, 221), t = 1 red (180, 4, 38),
// interpolated in his Msh space so lightness rises linearly to the middle
// and the hues stay apart. t is clamped to [-1, 1]. Returns sRGB-encoded
// values in [0, 1] (write them without a transfer curve).
glm::vec3 diverging_color(float t);

// Errors of this size or more take the map's end colours.
inline constexpr float kErrorImageRange = 0.5f;

// Colour of pixels not compared (no geometry, or outside the light's cone).
inline constexpr float kErrorImageBackground = 0.1f;

// The signed error technique - reference of the red channels, coloured by
// diverging_color(error / range), over the pixels compared (alpha 1 in
// both); other pixels are kErrorImageBackground grey. Alpha: 1 where
// compared. sRGB-encoded: write with PngEncoding::Linear. Throws
// RuntimeError if the sizes differ.
Image error_image(const Image& technique, const Image& reference, float range = kErrorImageRange);

}  // namespace penumbra
