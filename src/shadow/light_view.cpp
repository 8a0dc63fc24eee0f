#include "penumbra/shadow/light_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "shadow/polygon_clip.hpp"

namespace penumbra {

glm::vec3 stable_up(const glm::vec3& direction) {
  return std::abs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

void padded_depth_range(bool found, float zmin, float zmax, float& z0, float& z1) {
  if (!found) {
    zmin = 0.1f;  // nothing in view
    zmax = 1.0f;
  }
  // Pad so that the nearest and farthest surfaces do not touch the clip
  // planes, and keep the near plane far enough out for depth precision.
  z1 = zmax * 1.01f + 1e-3f;
  z0 = std::max(zmin * 0.99f, z1 * 1e-3f);
}

bool frustum_depth_range(const glm::mat4& view, float kx, float ky, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, float& zmin, float& zmax) {
  const std::array<HalfSpace, 4> sides = frustum_sides(view, kx, ky);
  const glm::vec4 depth = -matrix_row(view, 2);  // view depth is -z
  bool any = false;
  for_each_clipped_triangle(vertices, indices, sides, [&](const std::vector<glm::vec3>& polygon) {
    for (const glm::vec3& p : polygon) {
      const float z = glm::dot(depth, glm::vec4(p, 1.0f));
      if (z <= 0.0f) continue;
      zmin = std::min(zmin, z);
      zmax = std::max(zmax, z);
      any = true;
    }
  });
  return any;
}

bool frustum_depth_range(const glm::mat4& view, float kx, float ky, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, const CasterHierarchy& bounds,
                         float& zmin, float& zmax) {
  const std::array<HalfSpace, 4> sides = frustum_sides(view, kx, ky);
  // The sides meet only in front of the eye; a box is tested against each
  // on its own, so the plane through the eye also keeps out the boxes
  // behind it.
  const std::array<HalfSpace, 5> region = {sides[0], sides[1], sides[2], sides[3],
                                           coordinate_at_least(-matrix_row(view, 2), 0.0f)};
  // The near end may err by 1/32 of its distance (at most twice that, a
  // near plane up to 6 % closer: the position error it bounds grows as
  // much), the far end by 1/8 (depth precision hardly depends on it); finer
  // tolerances make the fit grow with the triangle count again
  // (benchmarks/fit_scaling.cpp).
  const CasterBoundsQuery query{.half_spaces = region,
                                .world_depth = -matrix_row(view, 2),
                                .frame_depth = -matrix_row(view, 2),
                                .relative_tolerance = glm::vec2(1.0f / 32.0f, 1.0f / 8.0f),
                                .in_front_only = true};
  return bounds.depth_range(vertices, indices, query, zmin, zmax);
}

float LightView::depth(const glm::vec3& world) const {
  const glm::vec3 p = glm::vec3(view * glm::vec4(world, 1.0f));
  return radial ? glm::length(p) : -p.z;
}

float LightView::relative_depth(const glm::vec3& world) const {
  return (depth(world) - z0) / (z1 - z0);
}

LightView fit_light_view(const Light& light, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, int map_size) {
  LightView lv;
  const glm::vec3 dir = glm::normalize(light.direction);
  const float size = static_cast<float>(map_size);

  if (light.type == LightType::Spot) {
    lv.perspective = true;
    lv.view = glm::lookAt(light.position, light.position + dir, stable_up(dir));
    const float fov = 2.0f * glm::radians(std::min(light.cone_degrees, 85.0f));
    // Depth range of the geometry the light's frustum sees: geometry behind
    // the light or outside its cone would only waste precision.
    float zmin = 1e30f, zmax = 0.0f;
    const float k = std::tan(0.5f * fov);
    const bool found = frustum_depth_range(lv.view, k, k, vertices, indices, zmin, zmax);
    padded_depth_range(found, zmin, zmax, lv.z0, lv.z1);
    lv.projection = glm::perspective(fov, 1.0f, lv.z0, lv.z1);
    lv.texel_world = 2.0f * std::tan(0.5f * fov) / size;
  } else {
    lv.perspective = false;
    lv.view = glm::lookAt(glm::vec3(0.0f), dir, stable_up(dir));
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      glm::vec3 p = glm::vec3(lv.view * glm::vec4(vertices[i], 1.0f));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    if (vertices.empty()) {
      lo = glm::vec3(-1.0f);
      hi = glm::vec3(1.0f);
    }
    // Square texels: the larger of the two extents sets the texel size.
    glm::vec2 center = 0.5f * (glm::vec2(lo) + glm::vec2(hi));
    float half = 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) * 1.01f + 1e-3f;
    float depth_pad = 0.01f * (hi.z - lo.z) + 1e-3f;
    lv.z0 = -hi.z - depth_pad;  // view space looks down -z: depth = -z
    lv.z1 = -lo.z + depth_pad;
    lv.projection = glm::ortho(center.x - half, center.x + half, center.y - half, center.y + half,
                               lv.z0, lv.z1);
    lv.texel_world = 2.0f * half / size;
  }
  lv.view_projection = lv.projection * lv.view;
  return lv;
}

}  // namespace penumbra
