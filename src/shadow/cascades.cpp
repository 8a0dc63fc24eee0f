#include "shadow/cascades.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

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

std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits,
                                         std::span<const Vertex> vertices, int map_size) {
  const glm::vec3 dir = glm::normalize(light.direction);
  // Rotation only: light space's origin is the world's, so snapping in it
  // is snapping to a grid fixed in the world.
  const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), dir, stable_up(dir));
  // Depth range of the whole scene along the light (casters outside a
  // cascade's slice still shadow it).
  float lo = 1e30f, hi = -1e30f;
  for (const Vertex& v : vertices) {
    const float z = (view * glm::vec4(v.position, 1.0f)).z;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  if (vertices.empty()) {
    lo = -1.0f;
    hi = 1.0f;
  }
  const float depth_pad = 0.01f * (hi - lo) + 1e-3f;
  const float z0 = -hi - depth_pad;  // view space looks down -z: depth = -z
  const float z1 = -lo + depth_pad;
  const float size = static_cast<float>(map_size);

  std::vector<LightView> views;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const Sphere sphere = frustum_slice_sphere(camera, splits[i], splits[i + 1]);
    // Half-width h = r + one texel of margin for the snap, 2 h / size a
    // texel: h = r / (1 - 2 / size).
    const float half = quantize_cascade_radius(sphere.radius) / (1.0f - 2.0f / size);
    const float texel = 2.0f * half / size;
    const glm::vec2 center = snap_to_texel(glm::vec2(view * glm::vec4(sphere.center, 1.0f)), texel);
    LightView lv;
    lv.perspective = false;
    lv.view = view;
    lv.projection =
        glm::ortho(center.x - half, center.x + half, center.y - half, center.y + half, z0, z1);
    lv.view_projection = lv.projection * lv.view;
    lv.z0 = z0;
    lv.z1 = z1;
    lv.texel_world = texel;
    views.push_back(lv);
  }
  return views;
}

}  // namespace penumbra
