#pragma once
// What share of a view's pixels get at least one shadow-map texel
// (Renderer::read_texel_density: texels per pixel, an area ratio), over
// the pixels a traced reference judges and over those it finds shadowed:
// where a shadow's shape shows, a pixel with less than one texel sees the
// map's blocks instead.
#include <cstdint>
#include <vector>

#include "io/image.hpp"

namespace penumbra {

struct TexelDensityShare {
  long pixels = 0;
  double median = 0.0;        // texels per pixel
  double at_least_one = 0.0;  // share of the pixels with >= 1 texel per pixel
};

struct TexelDensityStats {
  TexelDensityShare judged;    // every pixel the reference judges (lit or shadowed)
  TexelDensityShare shadowed;  // those whose reference shadow factor is below 1
  // The shadowed ones on the ground (reference/ground_pixels.hpp): where
  // the objects' shadows fall, whatever the objects' own faces get.
  TexelDensityShare shadowed_ground;
};

// A reference shadow factor below this counts as shadowed (1 - its value
// is more light lost than a traced reference's rounding).
inline constexpr float kShadowedBelow = 0.999f;

// `density` holds texels per pixel in red; `reference` the shadow factor
// in red, alpha >= 0.5 where judged; `ground` (row-major, as the images;
// empty: no ground) is 1 on the ground's pixels. Throws RuntimeError if
// the sizes differ.
TexelDensityStats texel_density_stats(const Image& density, const Image& reference,
                                      const std::vector<std::uint8_t>& ground = {});

// The same over the pixels with alpha >= 0.5 in `density` itself (every
// pixel that sees geometry), for a view with no reference.
TexelDensityShare texel_density_share(const Image& density);

}  // namespace penumbra
