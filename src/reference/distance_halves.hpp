#pragma once
// The compared pixels split into the near and far halves of the view, at
// the median camera distance of the pixels the reference judges (lit or
// shadowed): each half holds half of them, whatever the scene's size, so
// "the far half" means the same on a table top and on a 400-unit ground.
// The far half is where a shadow map's texels per pixel run out.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "io/image.hpp"
#include "render/surface_points.hpp"

namespace penumbra {

struct DistanceHalves {
  double median_distance = 0.0;  // from the camera, world units
  // Per pixel (row-major, rows top to bottom): 1 in the far half (farther
  // than the median), 0 in the near half or where not judged.
  std::vector<std::uint8_t> far;
  long near_pixels = 0, far_pixels = 0;
};

// Splits the pixels `judged` marks (alpha >= 0.5) that see a surface at
// the median of their distances from `camera`. The median pixel itself
// and those at its distance go to the near half. Throws RuntimeError if
// the sizes differ.
DistanceHalves split_at_median_distance(const SurfacePoints& surfaces, const glm::vec3& camera,
                                        const Image& judged);

// `image` with alpha 0 (not compared) outside one half.
Image only_half(const Image& image, const DistanceHalves& halves, bool far_half);

}  // namespace penumbra
