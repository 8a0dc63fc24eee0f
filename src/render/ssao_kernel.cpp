#include "render/ssao_kernel.hpp"

#include <cmath>
#include <numbers>

namespace penumbra {

double radical_inverse(unsigned base, unsigned i) {
  double inverse_base = 1.0 / base, scale = inverse_base, result = 0.0;
  for (; i > 0; i /= base, scale *= inverse_base) result += (i % base) * scale;
  return result;
}

std::vector<glm::vec4> ssao_kernel(int samples) {
  std::vector<glm::vec4> kernel;
  kernel.reserve(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const unsigned u = static_cast<unsigned>(i);
    // Midpoints of k strata: cos theta in (0, 1), never exactly tangent.
    const double cos_theta = (i + 0.5) / samples;
    const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
    const double phi = 2.0 * std::numbers::pi * radical_inverse(2, u);
    // i + 1: the radical inverse of 0 is 0, a point at the pixel itself.
    const double distance = radical_inverse(3, u + 1);
    kernel.emplace_back(static_cast<float>(std::cos(phi) * sin_theta),
                        static_cast<float>(std::sin(phi) * sin_theta),
                        static_cast<float>(cos_theta), static_cast<float>(distance));
  }
  return kernel;
}

}  // namespace penumbra
