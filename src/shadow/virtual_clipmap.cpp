#include "penumbra/shadow/virtual_clipmap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/shadow/cascades.hpp"
#include "shadow/polygon_clip.hpp"

namespace penumbra {

namespace {

// As cascades.cpp's: a level's depth range may err outwards by this
// fraction of its width (its maps store 32-bit z-bar, its biases are in
// texels).
constexpr float kLevelDepthTolerance = 1.0f / 32.0f;

int floor_div(int a, int b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

}  // namespace

float pixel_footprint_per_distance(const CameraFrustum& camera, int image_height) {
  return 2.0f * std::tan(0.5f * camera.fov_y) / static_cast<float>(std::max(image_height, 1));
}

glm::ivec2 virtual_page_slot(glm::ivec2 page) {
  return {page.x - floor_div(page.x, kVirtualPages) * kVirtualPages,
          page.y - floor_div(page.y, kVirtualPages) * kVirtualPages};
}

VirtualClipmap fit_virtual_clipmap(const Light& light, const CameraFrustum& camera,
                                   int image_height, PositionSpan vertices,
                                   std::span<const std::uint32_t> indices,
                                   const CasterHierarchy& bounds, const VirtualClipmap* previous) {
  VirtualClipmap clipmap;
  clipmap.pixel_angle = pixel_footprint_per_distance(camera, image_height);
  clipmap.camera = camera.position;
  clipmap.forward = glm::normalize(camera.forward);
  // All kMaxVirtualLevels levels, the coarsest's texel the power of two at
  // or below the pixel's footprint at the far plane: then level 0's is at
  // or below the footprint at any near plane the renderer fits (at least
  // 1e-4 of the far one), and it depends on the far plane alone, which an
  // orbiting camera changes less than the near one. Levels no pixel reads
  // cost no pages.
  const int count = kMaxVirtualLevels;
  const float far_footprint = std::max(camera.far_plane * clipmap.pixel_angle, 1e-6f);
  const float finest = far_footprint / std::exp2(static_cast<float>(count - 1));
  clipmap.texel0 = std::exp2(std::floor(std::log2(finest)));
  const glm::mat4 view = cascade_light_frame(light);
  if (previous != nullptr && !previous->levels.empty() &&
      previous->levels.front().view.view != view) {
    previous = nullptr;  // another light direction: nothing to keep
  }
  if (previous != nullptr && previous->texel0 <= finest && previous->texel0 * 4.0f > finest) {
    clipmap.texel0 = previous->texel0;
  }

  const glm::vec4 light_x = matrix_row(view, 0), light_y = matrix_row(view, 1);
  const glm::vec4 light_depth = -matrix_row(view, 2);
  const glm::vec2 camera_light = glm::vec2(view * glm::vec4(camera.position, 1.0f));
  const float camera_depth = glm::dot(glm::vec3(light_depth), camera.position) + light_depth.w;
  for (int l = 0; l < count; ++l) {
    const float texel = clipmap.texel0 * std::exp2(static_cast<float>(l));
    const float page = texel * static_cast<float>(kVirtualPageTexels);
    VirtualLevel level;
    // The camera in the middle page (64 of 128), the level on the world's
    // page grid.
    level.origin = glm::ivec2(glm::floor(camera_light / page)) - glm::ivec2(kVirtualPages / 2);
    const glm::vec2 lo = glm::vec2(level.origin) * page;
    const glm::vec2 hi = lo + static_cast<float>(kVirtualPages) * page;
    const float half = 0.5f * (hi.x - lo.x);

    // Casters and receivers alike: the geometry in the level's column.
    const std::array<HalfSpace, 4> column = {
        coordinate_at_least(light_x, lo.x), coordinate_at_most(light_x, hi.x),
        coordinate_at_least(light_y, lo.y), coordinate_at_most(light_y, hi.y)};
    const CasterBoundsQuery query{.half_spaces = column,
                                  .world_depth = light_depth,
                                  .frame_depth = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f),
                                  .tolerance = glm::vec2(kLevelDepthTolerance * 2.0f * half)};
    float z_near = 1e30f, z_far = -1e30f;
    bounds.depth_range(vertices, indices, query, z_near, z_far);
    if (z_near > z_far) {  // an empty column: around the camera
      z_near = camera_depth - half;
      z_far = camera_depth + half;
    }
    // Padded and snapped as a cascade's range (cascades.cpp), so that a
    // camera move leaves it, and the level's cached pages, unchanged.
    const float pad = 0.01f * (z_far - z_near) + 2.0f * texel;
    const float span = quantize_cascade_radius(z_far - z_near + 2.0f * pad);
    const float step = span / 16.0f;
    LightView& lv = level.view;
    lv.perspective = false;
    lv.view = view;
    lv.z0 = std::floor((z_near - pad) / step) * step;
    lv.z1 = lv.z0 + span + step;
    if (previous != nullptr && previous->texel0 == clipmap.texel0 &&
        static_cast<std::size_t>(l) < previous->levels.size()) {
      const LightView& before = previous->levels[static_cast<std::size_t>(l)].view;
      if (before.z0 <= z_near - pad && before.z1 >= z_far + pad &&
          before.z1 - before.z0 <= 2.0f * (lv.z1 - lv.z0)) {
        lv.z0 = before.z0;
        lv.z1 = before.z1;
      }
    }
    lv.projection = glm::ortho(lo.x, hi.x, lo.y, hi.y, lv.z0, lv.z1);
    lv.view_projection = lv.projection * lv.view;
    lv.texel_world = texel;
    clipmap.levels.push_back(level);
  }
  return clipmap;
}

namespace {

// A perspective projection `p` with its depth range moved to [z0, z1]
// (glm::perspective's right-handed, -1..1 clip depth): its xy rows, and so
// every texel's place, stay as they are.
glm::mat4 with_depth_range(glm::mat4 p, float z0, float z1) {
  p[2][2] = -(z1 + z0) / (z1 - z0);
  p[3][2] = -(2.0f * z1 * z0) / (z1 - z0);
  return p;
}

}  // namespace

VirtualClipmap fit_virtual_spot_map(const LightView& spot, const CameraFrustum& camera,
                                    int image_height, const VirtualClipmap* previous) {
  VirtualClipmap map;
  map.pixel_angle = pixel_footprint_per_distance(camera, image_height);
  map.camera = camera.position;
  map.forward = glm::normalize(camera.forward);
  // Level 0's texel at unit depth: the projection's 2 / (cot(fov / 2) N).
  map.texel0 = 2.0f / (spot.projection[1][1] * static_cast<float>(kVirtualTexels));
  float z0 = spot.z0, z1 = spot.z1;
  const VirtualLevel* before =
      previous != nullptr && !previous->levels.empty() ? &previous->levels.front() : nullptr;
  if (before != nullptr && before->view.perspective && before->view.view == spot.view &&
      before->view.projection[0][0] == spot.projection[0][0] &&
      before->view.projection[1][1] == spot.projection[1][1] && before->view.z0 <= z0 &&
      before->view.z1 >= z1 && before->view.z1 - before->view.z0 <= 2.0f * (z1 - z0)) {
    z0 = before->view.z0;
    z1 = before->view.z1;
  } else {
    // Room for casters to move a little without a new range (every page
    // would render again); the near plane kept at least half as far.
    const float margin = 0.125f * (z1 - z0);
    z0 = std::max(z0 - margin, 0.5f * z0);
    z1 += margin;
  }
  for (int m = 0; m < kVirtualSpotLevels; ++m) {
    VirtualLevel level;
    level.texels = kVirtualTexels >> m;
    LightView& lv = level.view;
    lv = spot;
    lv.z0 = z0;
    lv.z1 = z1;
    lv.projection = with_depth_range(spot.projection, z0, z1);
    lv.view_projection = lv.projection * lv.view;
    lv.texel_world = map.texel0 * static_cast<float>(1 << m);
    map.levels.push_back(level);
  }
  return map;
}

float virtual_level_coordinate(const VirtualClipmap& clipmap, const glm::vec3& world,
                               const glm::vec3& normal) {
  glm::vec3 ray = world - clipmap.camera;
  const float d = std::max(glm::length(ray), 1e-30f);
  ray /= d;
  const float cos_axis = std::clamp(glm::dot(ray, clipmap.forward), 1e-3f, 1.0f);
  // Towards the light: a view's +z axis (its third row), or a spot's eye.
  const LightView& first = clipmap.levels.front().view;
  const glm::mat4& v = first.view;
  const glm::vec3 to_light = first.perspective
                                 ? glm::normalize(glm::vec3(glm::inverse(v)[3]) - world)
                                 : glm::vec3(v[0][2], v[1][2], v[2][2]);
  const float tilt = std::clamp(
      std::abs(glm::dot(normal, to_light)) / std::max(std::abs(glm::dot(normal, ray)), 1e-6f),
      1.0f / 16.0f, 1.0f);
  const float footprint = d * clipmap.pixel_angle * std::pow(cos_axis, 1.5f) * std::sqrt(tilt);
  // Level 0's texel at the point: a spot's grows with the depth.
  const float texel = first.perspective ? clipmap.texel0 * first.depth(world) : clipmap.texel0;
  return std::log2(std::max(footprint, 1e-30f) / std::max(texel, 1e-30f));
}

int virtual_level_of(const VirtualClipmap& clipmap, const glm::vec3& world, const glm::vec3& normal,
                     int bias) {
  const float l = std::floor(virtual_level_coordinate(clipmap, world, normal) -
                             0.5f * static_cast<float>(bias));
  return static_cast<int>(
      std::clamp(l, 0.0f, static_cast<float>(static_cast<int>(clipmap.levels.size()) - 1)));
}

std::pair<glm::ivec2, glm::ivec2> virtual_pages_of_box(const VirtualLevel& level,
                                                       const glm::vec3& lo, const glm::vec3& hi) {
  glm::vec2 box_lo(1e30f), box_hi(-1e30f);
  const int pages = level.texels / kVirtualPageTexels;
  if (level.view.perspective) {
    // The box's corners in the level's texels; a corner at or behind the
    // light's plane spreads the box over every page.
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
      const glm::vec4 clip = level.view.view_projection * glm::vec4(corner, 1.0f);
      if (clip.w <= 1e-6f) return {glm::ivec2(0), glm::ivec2(pages - 1)};
      const glm::vec2 texel =
          (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * static_cast<float>(level.texels);
      box_lo = glm::min(box_lo, texel);
      box_hi = glm::max(box_hi, texel);
    }
    // One texel of margin, as below.
    glm::ivec2 first = glm::ivec2(glm::floor((box_lo - 1.0f) / float(kVirtualPageTexels)));
    glm::ivec2 last = glm::ivec2(glm::floor((box_hi + 1.0f) / float(kVirtualPageTexels)));
    return {glm::max(first, glm::ivec2(0)), glm::min(last, glm::ivec2(pages - 1))};
  }
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const glm::vec2 p = glm::vec2(level.view.view * glm::vec4(corner, 1.0f));
    box_lo = glm::min(box_lo, p);
    box_hi = glm::max(box_hi, p);
  }
  const float page = level.view.texel_world * static_cast<float>(kVirtualPageTexels);
  // One texel of margin: the filters and the bilinear taps of the texels
  // at the box's edge.
  const float margin = level.view.texel_world;
  glm::ivec2 first = glm::ivec2(glm::floor((box_lo - margin) / page));
  glm::ivec2 last = glm::ivec2(glm::floor((box_hi + margin) / page));
  first = glm::max(first, level.origin);
  last = glm::min(last, level.origin + glm::ivec2(kVirtualPages - 1));
  return {first, last};
}

}  // namespace penumbra
