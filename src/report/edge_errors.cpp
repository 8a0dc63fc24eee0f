#include "report/edge_errors.hpp"

#include <cmath>

#include "penumbra/error.hpp"

namespace penumbra {

EdgeErrors edge_errors(const Image& technique, const Image& reference, int reach) {
  if (technique.width != reference.width || technique.height != reference.height) {
    throw RuntimeError("edge_errors: the images differ in size");
  }
  const auto compared = [&](int x, int y) {
    return technique.pixel(x, y)[3] >= 0.5f && reference.pixel(x, y)[3] >= 0.5f;
  };
  EdgeErrors e;
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      if (!compared(x, y)) continue;
      ++e.compared;
      const float r = reference.pixel(x, y)[0];
      if (std::abs(technique.pixel(x, y)[0] - r) <= 0.5f) continue;
      ++e.wrong;
      bool near = false;
      for (int dy = -reach; dy <= reach && !near; ++dy) {
        for (int dx = -reach; dx <= reach && !near; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= reference.width || v >= reference.height) continue;
          near = reference.pixel(u, v)[3] >= 0.5f && std::abs(reference.pixel(u, v)[0] - r) > 0.5f;
        }
      }
      e.near_edge += near;
    }
  }
  return e;
}

}  // namespace penumbra
