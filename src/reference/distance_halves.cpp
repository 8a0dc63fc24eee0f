#include "reference/distance_halves.hpp"

#include <algorithm>

#include "penumbra/error.hpp"

namespace penumbra {

DistanceHalves split_at_median_distance(const SurfacePoints& surfaces, const glm::vec3& camera,
                                        const Image& judged) {
  if (surfaces.width != judged.width || surfaces.height != judged.height) {
    throw RuntimeError("surfaces and the judged pixels differ in size");
  }
  DistanceHalves halves;
  halves.far.assign(surfaces.size(), 0);
  std::vector<double> distance(surfaces.size(), -1.0);
  std::vector<double> sorted;
  for (int y = 0; y < judged.height; ++y) {
    for (int x = 0; x < judged.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * judged.width + x;
      if (judged.pixel(x, y)[3] < 0.5f || surfaces.covered[i] == 0) continue;
      distance[i] = glm::length(glm::dvec3(surfaces.position[i]) - glm::dvec3(camera));
      sorted.push_back(distance[i]);
    }
  }
  if (sorted.empty()) return halves;
  // The lower median: with an even count the halves are equal.
  const std::size_t middle = (sorted.size() - 1) / 2;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(middle),
                   sorted.end());
  halves.median_distance = sorted[middle];
  for (std::size_t i = 0; i < distance.size(); ++i) {
    if (distance[i] < 0.0) continue;
    const bool far = distance[i] > halves.median_distance;
    halves.far[i] = far ? 1 : 0;
    ++(far ? halves.far_pixels : halves.near_pixels);
  }
  return halves;
}

Image only_half(const Image& image, const DistanceHalves& halves, bool far_half) {
  Image out = image;
  for (std::size_t i = 0; i < halves.far.size() && 4 * i + 3 < out.rgba.size(); ++i) {
    if ((halves.far[i] != 0) != far_half) out.rgba[4 * i + 3] = 0.0f;
  }
  return out;
}

}  // namespace penumbra
