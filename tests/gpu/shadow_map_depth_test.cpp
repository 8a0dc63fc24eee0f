// The depth maps hold z-bar = (z - z0) / (z1 - z0) of the nearest caster
// in every kind of view, however the pass produces it (caster_position.glsl:
// the rasterizer's own depth for cascades, reversed z0 / z linearized once
// for spot lights, written radial depth for a point light's faces). Each
// texel is checked against the same quantity traced in double precision
// through its centre.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <optional>

#include "gpu_fixture.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kDepthMapSize = 64;
constexpr int kPlanes = 5;

// A stack of tilted planes, wide enough to fill most views, lit by one
// light.
Scene plane_stack(const Light& light) {
  testing::TestScene scene("plane stack");
  for (int i = 0; i < kPlanes; ++i) {
    scene.plane({0.0f, 0.3f * static_cast<float>(i), 0.0f}, 14.0f,
                {12.0f + 2.0f * static_cast<float>(i), 0.0f, 7.0f});
  }
  return scene.camera({0.0f, 6.0f, 9.0f}, {0.0f, 0.5f, 0.0f}).light(light);
}

struct Hit {
  int plane = -1;  // -1: nothing along the ray
  double depth = 0.0;
};

// The nearest triangle the ray from `origin` along `direction` meets at a
// depth of at least z0 (the view's own depth: along its axis, or for a cube
// face the distance from the light, whose shared z0 is a distance too), by
// Moller and Trumbore's test in double.
Hit trace(const TriangleMesh& mesh, const LightView& view, const glm::dvec3& origin,
          const glm::dvec3& direction) {
  const glm::dmat4 to_view(view.view);
  Hit nearest;
  double nearest_t = 1e300;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.vertices[mesh.indices[t]].position);
    const glm::dvec3 b(mesh.vertices[mesh.indices[t + 1]].position);
    const glm::dvec3 c(mesh.vertices[mesh.indices[t + 2]].position);
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) continue;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    const double hit_t = glm::dot(e2, q) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0 || hit_t <= 0.0 || hit_t >= nearest_t) continue;
    const glm::dvec3 in_view(to_view * glm::dvec4(origin + hit_t * direction, 1.0));
    const double depth = view.radial ? glm::length(in_view) : -in_view.z;
    if (depth < view.z0) continue;  // before the view's depth range
    nearest_t = hit_t;
    nearest.plane = static_cast<int>(t / (mesh.indices.size() / kPlanes));
    nearest.depth = depth;
  }
  return nearest;
}

// The traced hit through map point (x, y) (texel units, GL's rows).
Hit trace_map_point(const TriangleMesh& mesh, const LightView& view, double x, double y) {
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(view.view_projection));
  const glm::dvec2 ndc = glm::dvec2(x, y) / double(kDepthMapSize) * 2.0 - 1.0;
  const glm::dvec4 near_h = inverse * glm::dvec4(ndc, -1.0, 1.0);
  const glm::dvec4 far_h = inverse * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 near_point = glm::dvec3(near_h) / near_h.w;
  const glm::dvec3 far_point = glm::dvec3(far_h) / far_h.w;
  return trace(mesh, view, near_point, far_point - near_point);
}

struct MapCheck {
  int checked = 0;
  int skipped = 0;     // texels on a plane's edge: coverage decides, not depth
  double worst = 0.0;  // largest error, in units of the precision z-bar can have
};

// Compares one view's map with the traced z-bar at each texel centre. The
// unit of error is what float32 can resolve there: one ulp of z-bar plus
// one ulp of the depth z it is computed from, in z-bar units.
MapCheck check_map(const Image& map, const TriangleMesh& mesh, const LightView& view) {
  MapCheck check;
  const double range = double(view.z1) - view.z0;
  for (int row = 0; row < kDepthMapSize; ++row) {   // GL's row
    const int image_row = kDepthMapSize - 1 - row;  // read_shadow_view's rows run top down
    for (int column = 0; column < kDepthMapSize; ++column) {
      const double x = column + 0.5, y = row + 0.5;
      const Hit centre = trace_map_point(mesh, view, x, y);
      bool edge = false;
      for (auto [dx, dy] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}}) {
        edge = edge || trace_map_point(mesh, view, x + dx, y + dy).plane != centre.plane;
      }
      if (edge) {
        ++check.skipped;
        continue;
      }
      const double expected =
          centre.plane < 0 ? 1.0 : std::clamp((centre.depth - view.z0) / range, 0.0, 1.0);
      const double ulp = std::ldexp(1.0, -24);
      const double unit = ulp * (std::max(expected, 1e-3) + std::abs(centre.depth) / range);
      const double stored = map.pixel(column, image_row)[0];
      check.worst = std::max(check.worst, std::abs(stored - expected) / unit);
      ++check.checked;
    }
  }
  return check;
}

Light light_of(LightType type) {
  Light light;
  light.type = type;
  light.position = {1.0f, 7.0f, 2.0f};
  light.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.25f));
  light.cone_degrees = 35.0f;
  if (type == LightType::Point) light.position = {0.5f, 3.5f, 0.0f};
  return light;
}

class ShadowMapDepth : public GpuTest, public ::testing::WithParamInterface<LightType> {};

// Every texel of every view of the light (one spot view, the cascades, the
// six cube faces) within a few units of float32's precision of the traced
// z-bar. The cube faces' fragments write their depth as every caster's
// did before (measured: up to 6.6 units); the rasterizer's own depth
// (cascades: up to 3.5) and the spot's linearized reciprocal (2.5) are as
// close, so the maps every technique reads are what they were. Under the
// point light the planes nearest to it lie off the -y face's axis (their
// normals tilt by about 20 degrees), at a depth along it below the
// faces' radial z0: a caster pass clipped at z0 left them out.
TEST_P(ShadowMapDepth, MapsHoldTheTracedRelativeDepth) {
  const Scene scene = plane_stack(light_of(GetParam()));
  Renderer renderer(scene);
  RenderSettings render;
  render.width = 64;
  render.height = 48;
  ShadowSettings shadow;
  shadow.technique = Technique::Hard;
  shadow.map_size = kDepthMapSize;
  shadow.cascades = 2;
  renderer.render(render, shadow);
  const LightShadowViews& views = renderer.shadow_views(0);
  for (std::size_t v = 0; v < views.views.size(); ++v) {
    const Image map = renderer.read_shadow_view(renderer.first_view(0) + static_cast<int>(v));
    const MapCheck check = check_map(map, renderer.mesh(), views.views[v]);
    std::printf("view %zu: %d texels checked, %d on edges, worst %.2f units\n", v, check.checked,
                check.skipped, check.worst);
    EXPECT_GT(check.checked, kDepthMapSize * kDepthMapSize / 2) << "view " << v;
    EXPECT_LE(check.worst, 8.0) << "view " << v;
  }
}

INSTANTIATE_TEST_SUITE_P(EveryLightType, ShadowMapDepth,
                         ::testing::Values(LightType::Spot, LightType::Directional,
                                           LightType::Point),
                         testing::light_type_name);

}  // namespace
}  // namespace penumbra
