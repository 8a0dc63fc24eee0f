#include "penumbra/shadow/cascades.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

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

// Texels kept beyond the receivers (and their blockers' reach) when a
// cascade is fitted to them: filters read up to this far around a lookup
// (PCF's kernel, a blur's window, the normal offset), and the map reads
// "lit" past its edge.
constexpr float kReceiverMarginTexels = 16.0f;

// The square column of light space a cascade covers: centre +- half on
// the light's x and y (rows 0 and 1 of `light_frame`).
std::array<HalfSpace, 4> cascade_column(const glm::mat4& light_frame, const glm::vec2& center,
                                        float half) {
  const glm::vec4 light_x = matrix_row(light_frame, 0), light_y = matrix_row(light_frame, 1);
  return {
      coordinate_at_least(light_x, center.x - half), coordinate_at_most(light_x, center.x + half),
      coordinate_at_least(light_y, center.y - half), coordinate_at_most(light_y, center.y + half)};
}

// The column and the camera's slice: where a cascade's receivers are.
std::array<HalfSpace, 10> column_and_slice(const std::array<HalfSpace, 4>& column,
                                           const std::array<HalfSpace, 6>& slice) {
  std::array<HalfSpace, 10> both;
  std::copy(column.begin(), column.end(), both.begin());
  std::copy(slice.begin(), slice.end(), both.begin() + 4);
  return both;
}

// A cascade's light depths: the nearest geometry in its column (every
// caster that can shadow its receivers: along a directional light, a
// shadow's caster lies in the receiver's column) and the farthest of its
// receivers (the geometry in both the column and the camera's slice).
struct CascadeDepths {
  float caster_near = 0.0f;
  float receiver_far = 0.0f;
};

CascadeDepths cascade_depths(const CasterHierarchy& bounds, PositionSpan vertices,
                             std::span<const std::uint32_t> indices, const glm::mat4& light_frame,
                             const std::array<HalfSpace, 4>& column,
                             const std::array<HalfSpace, 6>& slice, float half,
                             const Sphere& slice_sphere) {
  const glm::vec4 light_depth = -matrix_row(light_frame, 2);
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
  const std::array<HalfSpace, 10> receivers = column_and_slice(column, slice);
  query.half_spaces = receivers;
  bounds.depth_range(vertices, indices, query, unused, receiver_far);
  if (caster_near > column_far) {  // an empty column: the slice's sphere
    const float c = glm::dot(glm::vec3(light_depth), slice_sphere.center);
    caster_near = c - slice_sphere.radius;
    column_far = c + slice_sphere.radius;
  }
  return {.caster_near = caster_near,
          .receiver_far = receiver_far >= caster_near ? receiver_far : column_far};
}

// The square fitted to a cascade's receivers: the light-space rectangle of
// the geometry in its slice of the camera's frustum (after Lauritzen et
// al., "Sample Distribution Shadow Maps", I3D 2011, section 4, from the
// scene's triangles rather than the depth buffer), widened by the reach of
// their blockers through the sun's disc and a margin of texels, its
// half-width rounded up to quantize_cascade_radius()'s grid. Empty where
// the slice holds no geometry.
struct ReceiverSquare {
  glm::vec2 center{0.0f};
  float half = 0.0f;
};

std::optional<ReceiverSquare> fit_receivers(const CasterHierarchy& bounds, PositionSpan vertices,
                                            std::span<const std::uint32_t> indices,
                                            const glm::mat4& light_frame,
                                            const std::array<HalfSpace, 4>& column,
                                            const std::array<HalfSpace, 6>& slice,
                                            const CascadeDepths& depths, float reach_slope,
                                            float size) {
  const std::array<HalfSpace, 10> receivers = column_and_slice(column, slice);
  // The light's x and y are the frame's: the extremes are exact.
  CasterBoundsQuery query{.half_spaces = receivers};
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (int axis = 0; axis < 2; ++axis) {
    query.world_depth = matrix_row(light_frame, axis);
    query.frame_depth = glm::vec4(0.0f);
    query.frame_depth[axis] = 1.0f;
    if (!bounds.depth_range(vertices, indices, query, lo[axis], hi[axis])) return std::nullopt;
  }
  // A receiver's blockers lie nearer the light, within the sun's angular
  // radius of its direction: at most reach_slope times the receivers'
  // depth span (from the nearest caster) off its column.
  const float reach = reach_slope * std::max(depths.receiver_far - depths.caster_near, 0.0f);
  const float extent = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) + reach;
  // One more texel of margin for the snap, as for the sphere (and an
  // eighth of the map at most for the filters, on the smallest maps).
  const float margin = std::min(kReceiverMarginTexels, size / 8.0f) + 1.0f;
  const float half = quantize_cascade_radius(extent) / (1.0f - 2.0f * margin / size);
  return ReceiverSquare{.center = 0.5f * (lo + hi), .half = half};
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
                                         std::span<const std::uint32_t> indices, int map_size,
                                         bool tight) {
  const CasterHierarchy bounds(vertices, indices, cascade_light_frame(light));
  return fit_cascade_views(light, camera, splits, blend, vertices, indices, bounds, map_size,
                           tight);
}

std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits, float blend,
                                         PositionSpan vertices,
                                         std::span<const std::uint32_t> indices,
                                         const CasterHierarchy& bounds, int map_size, bool tight) {
  const glm::mat4 view = cascade_light_frame(light);
  const float size = static_cast<float>(map_size);
  // tan of the sun's angular radius: a receiver's blockers lie within this
  // times their height above it of its column.
  const float reach_slope = std::tan(0.5f * glm::radians(light.sun_angle));

  std::vector<LightView> views;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const float d0 = cascade_slice_start(splits, blend, i), d1 = splits[i + 1];
    const Sphere sphere = frustum_slice_sphere(camera, d0, d1);
    // Half-width h = r + one texel of margin for the snap, 2 h / size a
    // texel: h = r / (1 - 2 / size).
    float half = quantize_cascade_radius(sphere.radius) / (1.0f - 2.0f / size);
    float texel = 2.0f * half / size;
    glm::vec2 center = snap_to_texel(glm::vec2(view * glm::vec4(sphere.center, 1.0f)), texel);
    const std::array<HalfSpace, 6> slice = camera_slice(camera, d0, d1);
    const std::array<HalfSpace, 4> sphere_column = cascade_column(view, center, half);
    CascadeDepths depths =
        cascade_depths(bounds, vertices, indices, view, sphere_column, slice, half, sphere);
    if (tight) {
      if (const std::optional<ReceiverSquare> fit = fit_receivers(
              bounds, vertices, indices, view, sphere_column, slice, depths, reach_slope, size)) {
        half = fit->half;
        texel = 2.0f * half / size;
        center = snap_to_texel(fit->center, texel);
        depths = cascade_depths(bounds, vertices, indices, view, cascade_column(view, center, half),
                                slice, half, sphere);
      }
    }
    const float far_end = depths.receiver_far;
    const float caster_near = depths.caster_near;
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
