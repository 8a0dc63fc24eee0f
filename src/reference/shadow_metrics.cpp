#include "reference/shadow_metrics.hpp"

#include <cmath>

#include "penumbra/error.hpp"

namespace penumbra {

ShadowMetrics compare_shadow(const Image& technique, const Image& reference) {
  if (technique.width != reference.width || technique.height != reference.height) {
    throw RuntimeError("shadow images to compare differ in size");
  }
  ShadowMetrics m;
  double sum_abs = 0.0, sum_sq = 0.0;
  long leaks = 0, over_dark = 0;
  for (int y = 0; y < technique.height; ++y) {
    for (int x = 0; x < technique.width; ++x) {
      const float* t = technique.pixel(x, y);
      const float* r = reference.pixel(x, y);
      if (t[3] < 0.5f || r[3] < 0.5f) continue;  // background
      const double error = std::abs(double(t[0]) - double(r[0]));
      ++m.pixels;
      sum_abs += error;
      sum_sq += error * error;
      m.max_error = std::max(m.max_error, error);
      leaks += r[0] < kLeakReferenceBelow && t[0] > kLeakTechniqueAbove;
      over_dark += r[0] > kOverDarkReferenceAbove && t[0] < kOverDarkTechniqueBelow;
    }
  }
  if (m.pixels > 0) {
    const double n = static_cast<double>(m.pixels);
    m.mean_absolute_error = sum_abs / n;
    m.rmse = std::sqrt(sum_sq / n);
    m.leak_fraction = static_cast<double>(leaks) / n;
    m.over_dark_fraction = static_cast<double>(over_dark) / n;
  }
  return m;
}

}  // namespace penumbra
