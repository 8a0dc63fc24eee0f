// The traced reference on geometry whose shadows are known in closed form,
// and on the default scene, where the area light's penumbra must widen with
// the blocker's height.
#include "reference/shadow_ray_tracer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

// A horizontal square at height y spanning [x0, x1] x [z0, z1].
void add_quad(TriangleMesh& mesh, float x0, float x1, float z0, float z1, float y) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const glm::vec3& p :
       {glm::vec3(x0, y, z0), glm::vec3(x1, y, z0), glm::vec3(x1, y, z1), glm::vec3(x0, y, z1)}) {
    mesh.vertices.push_back({p, glm::vec3(0.0f, 1.0f, 0.0f), 0});
  }
  for (std::uint32_t i : {0u, 2u, 1u, 0u, 3u, 2u}) mesh.indices.push_back(base + i);
}

// Points on the ground, facing up unless told.
SurfacePoints ground_points(const std::vector<glm::vec3>& points) {
  SurfacePoints s(static_cast<int>(points.size()), 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    s.position[i] = points[i];
    s.normal[i] = glm::vec3(0.0f, 1.0f, 0.0f);
    s.covered[i] = 1;
  }
  return s;
}

ReferenceLight spot_down(float height, float size) {
  ReferenceLight light;
  light.type = LightType::Spot;
  light.position = {0.0f, height, 0.0f};
  light.direction = {0.0f, -1.0f, 0.0f};
  light.size = size;
  light.cos_cone = std::cos(glm::radians(60.0f));
  return light;
}

TEST(ShadowRayTracer, PointLightGivesTheExactHardShadow) {
  TriangleMesh mesh;
  add_quad(mesh, -0.5f, 0.5f, -0.5f, 0.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  SurfacePoints s = ground_points({{0.0f, 0.0f, 0.0f},     // under the square
                                   {0.8f, 0.0f, 0.0f},     // its shadow ends at x = 0.5 * 3/2
                                   {0.7f, 0.0f, 0.0f},     // still inside it
                                   {0.0f, 0.0f, 0.0f},     // facing away (set below)
                                   {0.0f, 0.0f, 0.0f},     // no geometry (set below)
                                   {10.0f, 0.0f, 0.0f}});  // outside the 60-degree cone
  s.normal[3] = glm::vec3(0.0f, -1.0f, 0.0f);
  s.covered[4] = 0;
  const Image image = tracer.trace(s, spot_down(3.0f, 0.0f), 64);
  const float expected[6][2] = {{0, 1}, {1, 1}, {0, 1}, {0, 1}, {1, 0}, {1, 0}};
  for (int x = 0; x < 6; ++x) {
    EXPECT_EQ(image.pixel(x, 0)[0], expected[x][0]) << "point " << x;
    EXPECT_EQ(image.pixel(x, 0)[3], expected[x][1]) << "point " << x;
  }
}

// A square light 1 wide at height 2 over an occluding half-plane x < 0 at
// height 1: from the point (p, 0, 0), rays cross height 1 at (p + l) / 2,
// so the light's part l < -p is hidden and the visible fraction is
// 0.5 + p (for |p| <= 0.5). Stratified samples get it to within 1/N, plus
// what the ray offset (here 7e-4 up) shifts.
TEST(ShadowRayTracer, AreaLightGivesTheVisibleFraction) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  const std::vector<float> offsets = {-0.6f, -0.25f, 0.0f, 0.1f, 0.25f, 0.6f};
  std::vector<glm::vec3> points;
  for (float p : offsets) points.push_back({p, 0.0f, 0.3f});
  const Image image = tracer.trace(ground_points(points), spot_down(2.0f, 1.0f), 256);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const float expected = std::clamp(0.5f + offsets[i], 0.0f, 1.0f);
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], expected, 2.0f / 256.0f)
        << "offset " << offsets[i];
  }
}

// A point light with a spherical source 1 in diameter at height 2 over the
// same half-plane: from (p, 0, 0) the sphere is a disk of radius 0.5 facing
// the point, of which the part beyond the edge's image at -p is visible:
// the disk-segment fraction 1/2 + (asin(a) + a sqrt(1 - a^2)) / pi, a = 2p
// (exact at p = 0; for p != 0 the disk tilts by atan(p / 2), within 0.02).
TEST(ShadowRayTracer, SphericalPointLightGivesTheVisibleFraction) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  ReferenceLight light;
  light.type = LightType::Point;
  light.position = {0.0f, 2.0f, 0.3f};
  light.size = 1.0f;
  const std::vector<float> offsets = {-0.6f, -0.2f, 0.0f, 0.15f, 0.6f};
  std::vector<glm::vec3> points;
  for (float p : offsets) points.push_back({p, 0.0f, 0.3f});
  const Image image = tracer.trace(ground_points(points), light, 1024);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double a = std::clamp(2.0 * offsets[i], -1.0, 1.0);
    const double expected = 0.5 + (std::asin(a) + a * std::sqrt(1.0 - a * a)) / 3.14159265358979;
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], expected, 0.02) << "offset " << offsets[i];
    EXPECT_EQ(image.pixel(static_cast<int>(i), 0)[3], 1.0f) << "a point light has no cone";
  }
}

// A directional light whose square of directions is 0.4 wide at unit
// distance, shining straight down past the same half-plane: from (p, 0, 0)
// a ray leaving at tangent u crosses height 1 at p + u, so the visible
// fraction is (0.2 + p) / 0.4.
TEST(ShadowRayTracer, DirectionalAreaLightGivesTheVisibleFraction) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  ReferenceLight sun;
  sun.type = LightType::Directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.size = 0.4f;
  const std::vector<float> offsets = {-0.3f, -0.1f, 0.0f, 0.05f, 0.3f};
  std::vector<glm::vec3> points;
  for (float p : offsets) points.push_back({p, 0.0f, 0.0f});
  const Image image = tracer.trace(ground_points(points), sun, 400);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const float expected = std::clamp((0.2f + offsets[i]) / 0.4f, 0.0f, 1.0f);
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], expected, 2.0f / 400.0f)
        << "offset " << offsets[i];
    EXPECT_EQ(image.pixel(static_cast<int>(i), 0)[3], 1.0f);
  }
}

// Samples of the light below a receiver's tangent plane are hidden by the
// receiver itself: a wall facing +x whose plane cuts the light in half
// sees half of it.
TEST(ShadowRayTracer, ReceiverHidesTheLightBehindItsTangentPlane) {
  const ShadowRayTracer tracer(TriangleMesh{});
  SurfacePoints s = ground_points({{0.0f, 0.0f, 0.0f}});
  s.normal[0] = glm::vec3(1.0f, 0.0f, 0.0f);
  const Image image = tracer.trace(s, spot_down(2.0f, 1.0f), 256);
  EXPECT_NEAR(image.pixel(0, 0)[0], 0.5f, 1.0f / 256.0f);
}

// The 10 %-90 % width of the visibility's rise along a line of ground
// points, from the shadowed end.
float transition_width(const ShadowRayTracer& tracer, const ReferenceLight& light, glm::vec2 from,
                       glm::vec2 to) {
  constexpr int kPoints = 400;
  std::vector<glm::vec3> points;
  for (int i = 0; i < kPoints; ++i) {
    const glm::vec2 p = glm::mix(from, to, (i + 0.5f) / kPoints);
    points.push_back({p.x, 0.0f, p.y});
  }
  const Image image = tracer.trace(ground_points(points), light, 256);
  EXPECT_LT(image.pixel(0, 0)[0], 0.05f) << "the line must start in the umbra";
  EXPECT_GT(image.pixel(kPoints - 1, 0)[0], 0.95f) << "the line must end in the light";
  int i10 = -1, i90 = -1;
  for (int i = 0; i < kPoints; ++i) {
    const float v = image.pixel(i, 0)[0];
    if (i10 < 0 && v > 0.1f) i10 = i;
    if (i90 < 0 && v > 0.9f) i90 = i;
  }
  return static_cast<float>(i90 - i10) * glm::length(to - from) / kPoints;
}

// On the default scene with a 1-unit spot light, the high slab's shadow
// edge (blocker 3.8 above the ground) is soft and the box's shadow edge
// next to its foot (blocker about 0.25 above) is nearly hard, as the
// similar triangles of a finite light demand: penumbra width about
// w_light (d_receiver - d_blocker) / d_blocker, i.e. about 0.7 and 0.03.
TEST(ShadowRayTracer, PenumbraUnderTheHighSlabIsWiderThanAtTheBoxFoot) {
  const Scene scene = *builtin_scene("default");
  const TriangleMesh mesh = build_scene_mesh(scene);
  const ShadowRayTracer tracer(mesh);
  const Light& spot = scene.lights[0];
  ShadowSettings settings;
  settings.light_size = 1.0f;
  const ReferenceLight light =
      make_reference_light(spot, fit_light_view(spot, mesh, settings.map_size), settings);

  // Across the slab shadow's edge farthest from the spot light, where no
  // other shadow falls.
  const float slab = transition_width(tracer, light, {-0.8f, -0.2f}, {-0.8f, -1.6f});

  // Across the shadow edge that starts at the box's foot, 0.2 beyond the
  // box's corner that casts it (the corner farthest to one side as seen
  // from the light).
  const Shape& box = scene.shapes[1];
  const float angle = glm::radians(box.rotation_degrees.y);
  const glm::vec2 center(box.position.x, box.position.z);
  const glm::vec2 axis_x(std::cos(angle), -std::sin(angle)),
      axis_z(std::sin(angle), std::cos(angle));
  const glm::vec2 light_xz(spot.position.x, spot.position.z);
  const glm::vec2 away = glm::normalize(center - light_xz), side(away.y, -away.x);
  glm::vec2 corner = center;
  for (float sx : {-1.0f, 1.0f}) {
    for (float sz : {-1.0f, 1.0f}) {
      const glm::vec2 k = center + 0.5f * box.size.x * (sx * axis_x + sz * axis_z);
      if (glm::dot(k - center, side) > glm::dot(corner - center, side)) corner = k;
    }
  }
  const glm::vec2 along = glm::normalize(corner - light_xz);
  const glm::vec2 outward = glm::dot(side, glm::vec2(-along.y, along.x)) > 0.0f
                                ? glm::vec2(-along.y, along.x)
                                : glm::vec2(along.y, -along.x);
  const glm::vec2 foot = corner + 0.2f * along;
  const float box_foot =
      transition_width(tracer, light, foot - 0.5f * outward, foot + 0.5f * outward);

  std::printf("10%%-90%% penumbra: %.3f under the slab, %.3f at the box's foot\n", slab, box_foot);
  EXPECT_GT(slab, 0.4f);
  EXPECT_LT(box_foot, 0.1f);
  EXPECT_GT(slab, 5.0f * box_foot);
}

}  // namespace
}  // namespace penumbra
