#include "reference/source_point_sets.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/light_sampling.hpp"

namespace penumbra {

namespace {

// Enough sets that a pixel's neighbours practically never share its set,
// while all of them together stay within a few megabytes.
constexpr std::uint32_t kMostSets = 1024;
constexpr std::uint64_t kMostPoints = std::uint64_t{1} << 20;

// An unbiased, well-mixed 32-bit hash of the pixel index, so that
// neighbouring pixels pick unrelated sets. The "lowbias32" finalizer (C.
// Wellons, hash-prospector).
std::uint32_t hash_pixel(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// 1 - cos(theta) of a cone of half-angle theta, without cancellation.
float one_minus_cos(float theta) {
  const float s = std::sin(0.5f * theta);
  return 2.0f * s * s;
}

SourcePointKind kind_of(const ReferenceLight& light) {
  if (light.type == LightType::Directional) return SourcePointKind::SunDirection;
  if (light.type == LightType::Point && light.size > 0.0f) return SourcePointKind::SphereDiskPoint;
  return SourcePointKind::SquarePoint;
}

}  // namespace

SourcePointSets::SourcePointSets(const ReferenceLight& light, std::uint32_t count,
                                 std::uint32_t max_sets)
    : kind_(kind_of(light)),
      count_(light.size > 0.0f ? std::max(count, 1u) : 1u),
      sets_(static_cast<std::uint32_t>(std::clamp<std::uint64_t>(
          std::min<std::uint64_t>({max_sets, kMostSets, kMostPoints / count_}), 1, kMostSets))),
      values_(static_cast<std::size_t>(sets_) * count_ * 3) {
  const bool area = light.size > 0.0f;
  const float sun_one_minus_cos = one_minus_cos(0.5f * light.size);
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, sets_), [&](const auto& range) {
    CmjPointSet points;
    for (std::uint32_t k = range.begin(); k != range.end(); ++k) {
      if (area) points.generate(count_, k);
      float* x = values_.data() + static_cast<std::size_t>(k) * count_ * 3;
      float* y = x + count_;
      float* z = y + count_;
      for (std::uint32_t s = 0; s < count_; ++s) {
        const glm::vec2 u = area ? points.points()[s] : glm::vec2(0.5f);
        glm::vec3 v(0.0f);
        switch (kind_) {
          case SourcePointKind::SquarePoint: {
            // A square facing `direction`, `size` wide, centred on the
            // light (size 0: the light's position).
            const glm::vec2 offset = (u - 0.5f) * light.size;
            v = light.position + offset.x * light.axis_u + offset.y * light.axis_v;
            break;
          }
          case SourcePointKind::SunDirection: {
            // The disc of directions, uniform in solid angle.
            v = -light.direction;
            if (area) {
              const glm::vec3 c = uniform_cone(u, sun_one_minus_cos);
              v = glm::normalize(c.x * light.axis_u + c.y * light.axis_v - c.z * light.direction);
            }
            break;
          }
          case SourcePointKind::SphereDiskPoint:
            v = glm::vec3(concentric_disk(u), 0.0f);
            break;
        }
        x[s] = v.x;
        y[s] = v.y;
        z[s] = v.z;
      }
    }
  });
}

SourcePointSets::Set SourcePointSets::set(std::uint32_t k) const {
  const float* x = values_.data() + static_cast<std::size_t>(k) * count_ * 3;
  return {x, x + count_, x + 2 * count_};
}

SourcePointSets::Set SourcePointSets::set_for(std::uint32_t pixel) const {
  return set(hash_pixel(pixel) % sets_);
}

}  // namespace penumbra
