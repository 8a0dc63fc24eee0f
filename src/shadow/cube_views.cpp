#include "shadow/cube_views.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {

// The point of triangle abc nearest to p (Ericson, "Real-Time Collision
// Detection", 2005, section 5.1.5: Voronoi regions of the vertices, edges
// and face in turn).
glm::vec3 closest_point_on_triangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                    const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const float denominator = 1.0f / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

glm::vec3 cube_face_axis(int face) {
  static const glm::vec3 axes[kCubeFaces] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                             {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  return axes[face];
}

glm::vec3 cube_face_up(int face) {
  static const glm::vec3 ups[kCubeFaces] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                            {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  return ups[face];
}

int cube_face(const glm::vec3& d) {
  const glm::vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
  return d.z >= 0.0f ? 4 : 5;
}

float guard_band_half_width(int map_size, float guard_texels) {
  return 1.0f / (1.0f - 2.0f * guard_texels / static_cast<float>(map_size));
}

float guard_band_fov(int map_size, float guard_texels) {
  return 2.0f * std::atan(guard_band_half_width(map_size, guard_texels));
}

float guard_band_texels(const ShadowMapSettings& settings, int map_size) {
  if (!settings.guard_band) return 0.0f;
  // Texels the technique reads on either side of the lookup texel.
  float reach = 0.0f;
  switch (settings.technique) {
    case Technique::Pcf:
      reach = 0.5f * settings.pcf_width;
      break;
    // PCSS's blocker search and penumbra are capped at this width;
    // backprojection's blockers' region is not, and past the band it reads
    // the other faces (backprojection_cube_cell() in
    // shaders/shadow/backprojection.glsl).
    case Technique::Pcss:
    case Technique::Backprojection:
      reach = 0.5f * MAX_PCF_WIDTH;
      break;
    case Technique::Vsm:
    case Technique::Esm:
    case Technique::Msm:
    case Technique::Msm16:
    case Technique::Evsm2:
    case Technique::Evsm4:
      reach =
          settings.soft ? static_cast<float>(MAX_SOFT_RADIUS) : static_cast<float>(settings.blur);
      break;
    default:
      break;
  }
  // The lookup moves up to normal_offset texels; bilinear taps and the 2x2
  // compare read one more.
  const float margin = std::ceil(settings.normal_offset) + 2.0f;
  return std::min(std::ceil(reach) + margin, static_cast<float>(map_size) / 8.0f);
}

bool radial_depth_range(const glm::vec3& center, PositionSpan vertices,
                        std::span<const std::uint32_t> indices, float& zmin, float& zmax) {
  bool any = false;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3& a = vertices[indices[t]];
    const glm::vec3& b = vertices[indices[t + 1]];
    const glm::vec3& c = vertices[indices[t + 2]];
    zmin = std::min(zmin, glm::length(closest_point_on_triangle(center, a, b, c) - center));
    for (const glm::vec3* v : {&a, &b, &c}) zmax = std::max(zmax, glm::length(*v - center));
    any = true;
  }
  return any;
}

std::vector<LightView> fit_cube_views(const Light& light, PositionSpan vertices,
                                      std::span<const std::uint32_t> indices, int map_size,
                                      float guard_texels) {
  float zmin = 1e30f, zmax = 0.0f, z0 = 0.0f, z1 = 0.0f;
  const bool found = radial_depth_range(light.position, vertices, indices, zmin, zmax);
  padded_depth_range(found, zmin, zmax, z0, z1);
  const float t = guard_band_half_width(map_size, guard_texels);
  // Clip planes: a point at distance z0 inside the face's frustum has axial
  // depth at least z0 / sqrt(1 + 2 t^2) (at the frustum's corners), and
  // axial depth never exceeds the distance.
  const float near_plane = std::max(0.99f * z0 / std::sqrt(1.0f + 2.0f * t * t), z1 * 1e-4f);
  const float far_plane = 1.01f * z1;
  const glm::mat4 projection = glm::perspective(2.0f * std::atan(t), 1.0f, near_plane, far_plane);
  std::vector<LightView> views;
  for (int face = 0; face < kCubeFaces; ++face) {
    LightView lv;
    lv.perspective = true;
    lv.radial = true;
    lv.view =
        glm::lookAt(light.position, light.position + cube_face_axis(face), cube_face_up(face));
    lv.projection = projection;
    lv.view_projection = projection * lv.view;
    lv.z0 = z0;
    lv.z1 = z1;
    lv.texel_world = 2.0f * t / static_cast<float>(map_size);
    views.push_back(lv);
  }
  return views;
}

}  // namespace penumbra
