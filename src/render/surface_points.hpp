#pragma once
// The surfaces the camera sees, one per pixel: world position and normal,
// rebuilt from the G-buffer. What the reference ray tracer shoots its
// shadow rays from, so that it judges exactly the points the lighting pass
// shades. No OpenGL here: the tracer and the tests build these by hand too.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra {

struct SurfacePoints {
  int width = 0;
  int height = 0;
  // Row-major, rows top to bottom (like Image); entries of uncovered
  // pixels are unspecified.
  std::vector<glm::vec3> position;    // world space
  std::vector<glm::vec3> normal;      // unit, facing the camera's side of the surface
  std::vector<std::uint8_t> covered;  // 1 where the pixel sees geometry
  // A bound of the distance along the normal between `position` and the
  // triangle the pixel was rasterized from: the error of rebuilding it from
  // the depth buffer (render/depth_position_error.hpp). 0 for points known
  // exactly. The reference tracer starts shadow rays at least this far
  // above the surface.
  std::vector<float> position_error;

  SurfacePoints() = default;
  SurfacePoints(int w, int h)
      : width(w),
        height(h),
        position(static_cast<std::size_t>(w) * h),
        normal(static_cast<std::size_t>(w) * h),
        covered(static_cast<std::size_t>(w) * h, 0),
        position_error(static_cast<std::size_t>(w) * h, 0) {}
  [[nodiscard]] std::size_t size() const { return covered.size(); }
  // position_error[i], or 0 where the points were built without bounds.
  [[nodiscard]] float error_bound(std::size_t i) const {
    return i < position_error.size() ? position_error[i] : 0.0f;
  }
};

}  // namespace penumbra
