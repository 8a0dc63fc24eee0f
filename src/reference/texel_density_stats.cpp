#include "reference/texel_density_stats.hpp"

#include <algorithm>
#include <vector>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

TexelDensityShare share_of(std::vector<double> values) {
  TexelDensityShare s;
  s.pixels = static_cast<long>(values.size());
  if (values.empty()) return s;
  const auto enough =
      std::count_if(values.begin(), values.end(), [](double d) { return d >= 1.0; });
  s.at_least_one = static_cast<double>(enough) / static_cast<double>(values.size());
  const std::size_t middle = (values.size() - 1) / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  s.median = values[middle];
  return s;
}

}  // namespace

TexelDensityStats texel_density_stats(const Image& density, const Image& reference,
                                      const std::vector<std::uint8_t>& ground) {
  if (density.width != reference.width || density.height != reference.height ||
      (!ground.empty() &&
       ground.size() != static_cast<std::size_t>(density.width) * density.height)) {
    throw RuntimeError("texel densities and reference differ in size");
  }
  std::vector<double> judged, shadowed, shadowed_ground;
  for (int y = 0; y < density.height; ++y) {
    for (int x = 0; x < density.width; ++x) {
      const float* d = density.pixel(x, y);
      const float* r = reference.pixel(x, y);
      if (d[3] < 0.5f || r[3] < 0.5f) continue;
      judged.push_back(d[0]);
      if (r[0] >= kShadowedBelow) continue;
      shadowed.push_back(d[0]);
      const std::size_t i = static_cast<std::size_t>(y) * density.width + x;
      if (!ground.empty() && ground[i] != 0) shadowed_ground.push_back(d[0]);
    }
  }
  return {share_of(std::move(judged)), share_of(std::move(shadowed)),
          share_of(std::move(shadowed_ground))};
}

TexelDensityShare texel_density_share(const Image& density) {
  std::vector<double> seen;
  for (std::size_t i = 0; i + 3 < density.rgba.size(); i += 4) {
    if (density.rgba[i + 3] >= 0.5f) seen.push_back(density.rgba[i]);
  }
  return share_of(std::move(seen));
}

}  // namespace penumbra
