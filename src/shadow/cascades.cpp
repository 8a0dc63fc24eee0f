#include "penumbra/shadow/cascades.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/shadow/caster_bounds.hpp"
#include "shadow/polygon_clip.hpp"

namespace penumbra {

std::vector<float> cascade_splits(float near_plane, float far_plane, int count, float lambda) {
  std::vector<float> splits(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const double f = static_cast<double>(i) / count;
    const double log_split = near_plane * std::pow(double(far_plane) / near_plane, f);
    const double uniform_split = near_plane + (double(far_plane) - near_plane) * f;
    splits[static_cast<std::size_t>(i)] =
        static_cast<float>(lambda * log_split + (1.0 - lambda) * uniform_split);
  }
  splits.front() = near_plane;  // exact ends, whatever the rounding
  splits.back() = far_plane;
  return splits;
}

Sphere frustum_slice_sphere(const CameraFrustum& camera, float d0, float d1) {
  const double ky = std::tan(0.5 * camera.fov_y);
  const double k2 = ky * ky * (1.0 + double(camera.aspect) * camera.aspect);
  double c = 0.5 * (double(d0) + d1) * (1.0 + k2);
  double r2 = 0.0;
  if (c >= d1) {
    c = d1;
    r2 = std::max((double(d1) - d0) * (double(d1) - d0) + d0 * double(d0) * k2,
                  d1 * double(d1) * k2);
  } else {
    r2 = (c - d0) * (c - d0) + d0 * double(d0) * k2;
  }
  Sphere s;
  s.center = camera.position + static_cast<float>(c) * camera.forward;
  s.radius = static_cast<float>(std::sqrt(r2));
  return s;
}

float quantize_cascade_radius(float radius) {
  return std::exp2(std::ceil(8.0f * std::log2(std::max(radius, 1e-6f))) / 8.0f);
}

glm::vec2 snap_to_texel(const glm::vec2& p, float texel) {
  return glm::vec2(std::round(p.x / texel), std::round(p.y / texel)) * texel;
}

float cascade_slice_start(std::span<const float> splits, float blend, std::size_t i) {
  if (i == 0) return splits[0];
  return splits[i] - blend * (splits[i] - splits[i - 1]);
}

namespace {

// How far, as a fraction of a cascade's width, its depth range may err
// outwards (twice this at most: caster_bounds.hpp). The maps store 32-bit
// z-bar and their biases are in texels, so a range a few percent wider
// costs no visible precision; a finer tolerance makes a fit after a camera
// move grow with the triangle count again (benchmarks/fit_scaling.cpp).
constexpr float kCascadeDepthTolerance = 1.0f / 32.0f;

// The half-spaces of the camera frustum's slice between view depths d0 and
// d1.
std::array<HalfSpace, 6> camera_slice(const CameraFrustum& camera, float d0, float d1) {
  const glm::mat4 view = glm::lookAt(camera.position, camera.position + camera.forward, camera.up);
  const float ky = std::tan(0.5f * camera.fov_y), kx = camera.aspect * ky;
  const std::array<HalfSpace, 4> sides = frustum_sides(view, kx, ky);
  const glm::vec4 depth = -matrix_row(view, 2);  // view depth is -z
  return {coordinate_at_least(depth, d0),
          coordinate_at_most(depth, d1),
          sides[0],
          sides[1],
          sides[2],
          sides[3]};
}

}  // namespace

glm::mat4 cascade_light_frame(const Light& light) {
  const glm::vec3 dir = glm::normalize(light.direction);
  // Rotation only: light space's origin is the world's, so snapping in it
  // is snapping to a grid fixed in the world.
  return glm::lookAt(glm::vec3(0.0f), dir, stable_up(dir));
}

std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits, float blend,
                                         PositionSpan vertices,
                                         std::span<const std::uint32_t> indices, int map_size) {
  const CasterHierarchy bounds(vertices, indices, cascade_light_frame(light));
  return fit_cascade_views(light, camera, splits, blend, vertices, indices, bounds, map_size);
}

std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits, float blend,
                                         PositionSpan vertices,
                                         std::span<const std::uint32_t> indices,
                                         const CasterHierarchy& bounds, int map_size) {
  const glm::mat4 view = cascade_light_frame(light);
  const glm::vec4 light_x = matrix_row(view, 0), light_y = matrix_row(view, 1);
  const glm::vec4 light_depth = -matrix_row(view, 2);
  const float size = static_cast<float>(map_size);

  std::vector<LightView> views;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const float d0 = cascade_slice_start(splits, blend, i), d1 = splits[i + 1];
    const Sphere sphere = frustum_slice_sphere(camera, d0, d1);
    // Half-width h = r + one texel of margin for the snap, 2 h / size a
    // texel: h = r / (1 - 2 / size).
    const float half = quantize_cascade_radius(sphere.radius) / (1.0f - 2.0f / size);
    const float texel = 2.0f * half / size;
    const glm::vec2 center = snap_to_texel(glm::vec2(view * glm::vec4(sphere.center, 1.0f)), texel);

    // Casters: the geometry in the column; receivers: the part of it in
    // the camera's slice as well.
    const std::array<HalfSpace, 4> column = {coordinate_at_least(light_x, center.x - half),
                                             coordinate_at_most(light_x, center.x + half),
                                             coordinate_at_least(light_y, center.y - half),
                                             coordinate_at_most(light_y, center.y + half)};
    const std::array<HalfSpace, 6> slice = camera_slice(camera, d0, d1);
    std::array<HalfSpace, 10> column_slice;
    std::copy(column.begin(), column.end(), column_slice.begin());
    std::copy(slice.begin(), slice.end(), column_slice.begin() + 4);
    // Light depth is minus the frame's z, so boxes inside the column give
    // exact extremes; boxes across its edges are opened only where they
    // could widen the range by more than kCascadeDepthTolerance of the
    // cascade's width.
    CasterBoundsQuery query{.half_spaces = column,
                            .world_depth = light_depth,
                            .frame_depth = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f),
                            .tolerance = glm::vec2(kCascadeDepthTolerance * 2.0f * half)};
    // (The receivers' near end is not needed: starting it at -infinity
    // lets the search skip every box that cannot raise their far end.)
    float caster_near = 1e30f, column_far = -1e30f, receiver_far = -1e30f, unused = -1e30f;
    bounds.depth_range(vertices, indices, query, caster_near, column_far);
    query.half_spaces = column_slice;
    bounds.depth_range(vertices, indices, query, unused, receiver_far);
    if (caster_near > column_far) {  // an empty column: the slice's sphere
      const float c = glm::dot(glm::vec3(light_depth), sphere.center);
      caster_near = c - sphere.radius;
      column_far = c + sphere.radius;
    }
    const float far_end = receiver_far >= caster_near ? receiver_far : column_far;
    // Pad so that no surface touches a clip plane, and the lookups of the
    // receivers at the far end (moved by the normal offset, read over a
    // filter's window) stay inside.
    const float pad = 0.01f * (far_end - caster_near) + 2.0f * texel;
    LightView lv;
    lv.perspective = false;
    lv.view = view;
    // Stable bounds (like the texel-snapped extent, so a small camera move
    // leaves the maps unchanged): the span rounded up to the radius grid,
    // the near end snapped down to a sixteenth of it.
    const float span = quantize_cascade_radius(far_end - caster_near + 2.0f * pad);
    const float step = span / 16.0f;
    lv.z0 = std::floor((caster_near - pad) / step) * step;
    lv.z1 = lv.z0 + span + step;
    lv.projection = glm::ortho(center.x - half, center.x + half, center.y - half, center.y + half,
                               lv.z0, lv.z1);
    lv.view_projection = lv.projection * lv.view;
    lv.texel_world = texel;
    views.push_back(lv);
  }
  return views;
}

}  // namespace penumbra
