#include "report/edge_errors.hpp"

#include <cmath>

#include "penumbra/error.hpp"

namespace penumbra {

namespace {

// Whether a compared pixel of the reference within `reach` of (x, y)
// differs from the reference at (x, y) by more than a half.
bool near_reference_edge(const Image& reference, int x, int y, int reach) {
  const float r = reference.pixel(x, y)[0];
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= reference.width || v >= reference.height) continue;
      if (reference.pixel(u, v)[3] >= 0.5f && std::abs(reference.pixel(u, v)[0] - r) > 0.5f) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

Image at_reference_edges(const Image& technique, const Image& reference, int reach) {
  if (technique.width != reference.width || technique.height != reference.height) {
    throw RuntimeError("at_reference_edges: the images differ in size");
  }
  Image edges = technique;
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      if (!near_reference_edge(reference, x, y, reach)) edges.pixel(x, y)[3] = 0.0f;
    }
  }
  return edges;
}

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
      e.near_edge += near_reference_edge(reference, x, y, reach) ? 1 : 0;
    }
  }
  return e;
}

}  // namespace penumbra
