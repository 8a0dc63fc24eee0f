// The traced reference on geometry whose shadows are known in closed form,
// and on the default scene, where the area light's penumbra must widen with
// the blocker's height.
#include "reference/shadow_ray_tracer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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
  // Value and alpha: the point facing away gets no light at all, so its
  // factor is not judged.
  const float expected[6][2] = {{0, 1}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 0}};
  for (int x = 0; x < 6; ++x) {
    EXPECT_EQ(image.pixel(x, 0)[0], expected[x][0]) << "point " << x;
    EXPECT_EQ(image.pixel(x, 0)[3], expected[x][1]) << "point " << x;
  }
}

// The form factor from a point to a rectangle parallel to its surface,
// with one corner straight above the point, X and Y its sides over the
// height (the standard closed form; e.g. Howell's catalogue, C-11), times
// pi: the irradiance a Lambertian rectangle of unit radiance gives.
double corner_form_factor(double x, double y) {
  const double a = std::sqrt(1.0 + x * x), b = std::sqrt(1.0 + y * y);
  return 0.5 * (x / a * std::atan(y / a) + y / b * std::atan(x / b));
}

// The same for the rectangle [x0, x1] x [z0, z1] (relative to the point)
// at height h, by signed corner rectangles.
double rectangle_form_factor(double x0, double x1, double z0, double z1, double h) {
  auto corner = [h](double x, double z) {
    const double sign = (x < 0.0 ? -1.0 : 1.0) * (z < 0.0 ? -1.0 : 1.0);
    return sign * corner_form_factor(std::abs(x) / h, std::abs(z) / h);
  };
  return corner(x1, z1) - corner(x0, z1) - corner(x1, z0) + corner(x0, z0);
}

// A square light 1 wide at height 2, facing down, over an occluding
// half-plane x < 0 at height 1: from the point (p, 0, 0.3), rays cross
// height 1 at (p + l) / 2, so the light's part l < -p is hidden. The
// shadow factor is the form factor of the visible part over the whole
// square's; the old unweighted visible fraction 0.5 + p is off by 0.027 at
// p = +-0.25, beyond the tolerance.
TEST(ShadowRayTracer, SquareLightGivesTheFormFactorRatio) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  const std::vector<float> offsets = {-0.6f, -0.25f, 0.0f, 0.1f, 0.25f, 0.6f};
  std::vector<glm::vec3> points;
  for (float p : offsets) points.push_back({p, 0.0f, 0.3f});
  const Image image = tracer.trace(ground_points(points), spot_down(2.0f, 1.0f), 1024);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double p = offsets[i], z0 = 0.3;
    const double lo = std::max(-0.5, -p);
    const double whole = rectangle_form_factor(-0.5 - p, 0.5 - p, -0.5 - z0, 0.5 - z0, 2.0);
    const double visible =
        lo >= 0.5 ? 0.0 : rectangle_form_factor(lo - p, 0.5 - p, -0.5 - z0, 0.5 - z0, 2.0);
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], visible / whole, 0.004) << "offset " << p;
  }
  // The weighting is what the test checks: at p = 0.25 it differs from
  // the unweighted fraction 0.75.
  EXPECT_GT(std::abs(rectangle_form_factor(-0.5, 0.25, -0.8, 0.2, 2.0) /
                         rectangle_form_factor(-0.75, 0.25, -0.8, 0.2, 2.0) -
                     0.75),
            0.02);
}

// The cos(theta_receiver)-weighted fraction of a cone of directions
// (around `axis`, half-angle `alpha`) that a receiver at (p, 0, .) facing
// up sees past a half-plane x < 0 at height 1, by quadrature over the
// cone: a direction w crosses height 1 at x = p + w.x / w.y.
double cone_ratio(double p, glm::dvec3 axis, double alpha) {
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
  constexpr int kTheta = 400, kPhi = 800;
  double lit = 0.0, all = 0.0;
  for (int i = 0; i < kTheta; ++i) {
    const double theta = alpha * (i + 0.5) / kTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * 3.14159265358979 * (j + 0.5) / kPhi;
      const glm::dvec3 w =
          std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * v) + std::cos(theta) * axis;
      const double weight = std::max(w.y, 0.0) * std::sin(theta);
      all += weight;
      if (p + w.x / w.y >= 0.0) lit += weight;
    }
  }
  return lit / all;
}

// A point light with a spherical source 1 in diameter at height 2 over the
// same half-plane: the sphere fills a cone of directions, each weighted by
// cos(theta_receiver).
TEST(ShadowRayTracer, SphericalPointLightGivesTheWeightedFraction) {
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
    const glm::dvec3 to_centre(-offsets[i], 2.0, 0.0);
    const double expected =
        cone_ratio(offsets[i], glm::normalize(to_centre), std::asin(0.5 / glm::length(to_centre)));
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], expected, 0.004) << "offset " << offsets[i];
    EXPECT_EQ(image.pixel(static_cast<int>(i), 0)[3], 1.0f) << "a point light has no cone";
  }
}

// A directional light whose disc of directions is 0.4 radians across,
// shining straight down past the same half-plane.
TEST(ShadowRayTracer, DirectionalAreaLightGivesTheWeightedDiscFraction) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  ReferenceLight sun;
  sun.type = LightType::Directional;
  sun.direction = {0.0f, -1.0f, 0.0f};
  sun.size = 0.4f;
  const std::vector<float> offsets = {-0.3f, -0.1f, 0.0f, 0.05f, 0.15f, 0.3f};
  std::vector<glm::vec3> points;
  for (float p : offsets) points.push_back({p, 0.0f, 0.0f});
  const Image image = tracer.trace(ground_points(points), sun, 1024);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double expected = cone_ratio(offsets[i], glm::dvec3(0.0, 1.0, 0.0), 0.2);
    EXPECT_NEAR(image.pixel(static_cast<int>(i), 0)[0], expected, 0.004) << "offset " << offsets[i];
    EXPECT_EQ(image.pixel(static_cast<int>(i), 0)[3], 1.0f);
  }
}

// A point nothing occludes reads exactly 1 from every kind of source,
// whatever part of the source its tangent plane cuts off: the same samples
// make both sums.
TEST(ShadowRayTracer, UnoccludedPointsReadExactlyOne) {
  const ShadowRayTracer tracer(TriangleMesh{});
  SurfacePoints s = ground_points({{0.0f, 0.0f, 0.0f}, {0.3f, 0.0f, 0.2f}, {-1.0f, 0.5f, 0.0f}});
  s.normal[1] = glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f));
  s.normal[2] = glm::normalize(glm::vec3(-0.3f, 0.1f, 1.0f));
  ReferenceLight sphere;
  sphere.type = LightType::Point;
  sphere.position = {0.2f, 2.0f, 0.1f};
  sphere.size = 1.5f;
  ReferenceLight sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.size = 0.3f;
  for (const ReferenceLight& light : {spot_down(2.0f, 1.5f), sphere, sun}) {
    const Image image = tracer.trace(s, light, 64);
    for (int x = 0; x < 3; ++x) {
      EXPECT_EQ(image.pixel(x, 0)[0], 1.0f)
          << "light type " << static_cast<int>(light.type) << ", point " << x;
    }
  }
}

// Parts of the light below a receiver's tangent plane send it no light
// with or without occluders: a wall facing +x whose plane cuts the square
// light in half is fully lit (the old fraction read 0.5), and an occluder
// hiding the half z < 0 of the light leaves half of what the wall sees
// (by symmetry in z), not a quarter.
TEST(ShadowRayTracer, LightBehindTheTangentPlaneCountsInNeitherSum) {
  SurfacePoints s = ground_points({{0.0f, 0.0f, 0.0f}});
  s.normal[0] = glm::vec3(1.0f, 0.0f, 0.0f);
  const ShadowRayTracer open(TriangleMesh{});
  EXPECT_EQ(open.trace(s, spot_down(2.0f, 1.0f), 256).pixel(0, 0)[0], 1.0f);
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 5.0f, -5.0f, 0.0f, 1.0f);
  const ShadowRayTracer half(mesh);
  EXPECT_NEAR(half.trace(s, spot_down(2.0f, 1.0f), 1024).pixel(0, 0)[0], 0.5f, 0.01f);
}

// A surface whose shading normal leans towards a low sun, on a flat mesh:
// the part of the sun above the shading normal's horizon but below the
// triangle's own plane counts in both sums, as in Cycles (whose reflection
// takes the shading normal's side), and the triangle itself shadows it
// (its flat vertex normals lift nothing). So the point reads the part of
// the light that comes from above the plane, and, with the sun all below
// the plane, 0: judged, and dark.
TEST(ShadowRayTracer, LightBelowTheTrianglesPlaneCountsInBothSums) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 5.0f, -5.0f, 5.0f, 0.0f);
  const ShadowRayTracer tracer(mesh);
  SurfacePoints s = ground_points({{0.1f, 0.0f, 0.2f}});
  s.position_error[0] = 1e-4f;
  const float tilt = glm::radians(10.0f);
  s.normal[0] = glm::vec3(-std::sin(tilt), std::cos(tilt), 0.0f);
  ReferenceLight sun;
  sun.type = LightType::Directional;
  // Towards the light: 1 degree below the horizon, from -x; 10 degrees
  // across, so part of it is above the plane.
  const float elevation = glm::radians(-1.0f);
  sun.direction = glm::vec3(std::cos(elevation), -std::sin(elevation), 0.0f);
  sun.axis_u = glm::vec3(0.0f, 0.0f, 1.0f);
  sun.axis_v = glm::normalize(glm::cross(sun.direction, sun.axis_u));
  sun.size = glm::radians(10.0f);
  const Image partly = tracer.trace(s, sun, 256);
  EXPECT_GT(partly.pixel(0, 0)[0], 0.1f);
  EXPECT_LT(partly.pixel(0, 0)[0], 0.9f);
  EXPECT_EQ(partly.pixel(0, 0)[3], 1.0f);
  const float lower = glm::radians(-6.0f);
  sun.direction = glm::vec3(std::cos(lower), -std::sin(lower), 0.0f);
  sun.axis_v = glm::normalize(glm::cross(sun.direction, sun.axis_u));
  const Image hidden = tracer.trace(s, sun, 256);
  EXPECT_EQ(hidden.pixel(0, 0)[0], 0.0f);
  EXPECT_EQ(hidden.pixel(0, 0)[3], 1.0f);
}

// Shadow rays start on the smooth surface the vertex normals describe
// where the light grazes the surface (the terminator model,
// reference/terminator_offset.hpp): under a coarse cap whose corner
// normals lean outwards the smooth surface lies well above the flat
// triangles' centre, so a low wall that a grazing sun's ray from the
// triangle would meet does not shadow the point; on the same quad with
// flat normals it does. Where the light faces the surface, its rays start
// on the triangle whatever the normals: a small occluder just above the
// point shadows it.
TEST(ShadowRayTracer, GrazingRaysStartOnTheSmoothSurfaceOfTheVertexNormals) {
  for (const bool smooth : {true, false}) {
    TriangleMesh mesh;
    add_quad(mesh, -1.0f, 1.0f, -1.0f, 1.0f, 0.0f);
    if (smooth) {
      for (Vertex& v : mesh.vertices) {
        v.normal = glm::normalize(glm::vec3(0.5f * v.position.x, 1.0f, 0.5f * v.position.z));
      }
    }
    // The wall, 4 cm high, half a unit towards the sun.
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const glm::vec3& p : {glm::vec3(0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 0.0f, 0.5f),
                               glm::vec3(0.5f, 0.04f, 0.5f), glm::vec3(0.5f, 0.04f, -0.5f)}) {
      mesh.vertices.push_back({p, glm::vec3(-1.0f, 0.0f, 0.0f), 0});
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    add_quad(mesh, -0.1f, 0.1f, -0.1f, 0.1f, 0.05f);  // the occluder above the point
    const ShadowRayTracer tracer(mesh);
    const SurfacePoints s = ground_points({{0.0f, 0.0f, 0.0f}});
    ReferenceLight sun;
    sun.type = LightType::Directional;
    sun.axis_u = glm::vec3(0.0f, 0.0f, 1.0f);
    for (const float elevation : {3.0f, 60.0f}) {
      const float e = glm::radians(elevation);
      sun.direction = -glm::vec3(std::cos(e), std::sin(e), 0.0f);
      sun.axis_v = glm::normalize(glm::cross(sun.direction, sun.axis_u));
      const float lit = tracer.trace(s, sun, 1).pixel(0, 0)[0];
      EXPECT_EQ(lit, smooth && elevation < 10.0f ? 1.0f : 0.0f)
          << (smooth ? "smooth" : "flat") << ", sun at " << elevation << " degrees";
    }
  }
}

// A square source emits from its front only: a point above a downward
// spot light, facing it, gets no light (0 and not judged, as a surface
// facing away).
TEST(ShadowRayTracer, SquareLightSendsNothingBehindIt) {
  const ShadowRayTracer tracer(TriangleMesh{});
  SurfacePoints s = ground_points({{0.5f, 3.0f, 0.0f}});
  s.normal[0] = glm::vec3(0.0f, -1.0f, 0.0f);
  const Image image = tracer.trace(s, spot_down(2.0f, 1.0f), 64);
  EXPECT_EQ(image.pixel(0, 0)[0], 0.0f);
  EXPECT_EQ(image.pixel(0, 0)[3], 0.0f) << "no light arrives: not judged";
}

// Shadow rays start above the point by its position error: a point that
// rounding left 1e-3 below a plane it lies on, with that error bound,
// is lit; without the bound the plane shadows it.
TEST(ShadowRayTracer, RaysStartAboveThePositionErrorBound) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 5.0f, -5.0f, 5.0f, 0.0f);
  const ShadowRayTracer tracer(mesh);
  SurfacePoints s = ground_points({{0.1f, -1e-3f, 0.2f}, {0.1f, -1e-3f, 0.2f}});
  s.position_error[0] = 1.5e-3f;
  const Image image = tracer.trace(s, spot_down(2.0f, 0.0f), 1);
  EXPECT_EQ(image.pixel(0, 0)[0], 1.0f);
  EXPECT_EQ(image.pixel(1, 0)[0], 0.0f);
}

// Surface points that are not finite, or absurd (far outside the scene, or
// with an error bound larger than it), are not traced: nothing aborts
// inside Embree, and they are not judged. Their neighbours, in the same
// packets, keep their answers. Each case with a point light and with a
// square one.
TEST(ShadowRayTracer, NonFiniteAndAbsurdPointsAreNotJudged) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);  // shadows x < 0
  add_quad(mesh, -5.0f, 5.0f, -5.0f, 5.0f, 0.0f);  // the ground
  const ShadowRayTracer tracer(mesh);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Bad {
    glm::vec3 position, normal;
    float error;
  };
  const std::vector<Bad> bad = {
      {{nan, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {{0.5f, inf, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {{0.5f, 0.0f, -inf}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {{1e38f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {{-1e38f, 1e38f, 1e38f}, {0.0f, 1.0f, 0.0f}, 0.0f},
      {{0.5f, 0.0f, 0.0f}, {nan, 1.0f, 0.0f}, 0.0f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, inf, 0.0f}, 0.0f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1e38f, 0.0f}, 0.0f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.0f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, nan},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, inf},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1e38f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 1e3f},
      {{0.5f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, -1.0f},
  };
  // Bad points between good ones: a good point at x = -1 (shadowed) and
  // x = 1 (lit) before each.
  SurfacePoints s(static_cast<int>(3 * bad.size()), 1);
  for (std::size_t b = 0; b < bad.size(); ++b) {
    for (std::size_t k = 0; k < 2; ++k) {
      s.position[3 * b + k] = {k == 0 ? -1.0f : 1.0f, 0.0f, 0.1f * static_cast<float>(b)};
      s.normal[3 * b + k] = {0.0f, 1.0f, 0.0f};
      s.covered[3 * b + k] = 1;
    }
    s.position[3 * b + 2] = bad[b].position;
    s.normal[3 * b + 2] = bad[b].normal;
    s.position_error[3 * b + 2] = bad[b].error;
    s.covered[3 * b + 2] = 1;
  }
  EXPECT_EQ(untraceable_points(s, mesh_extent(mesh)), static_cast<long>(bad.size()));
  for (const float size : {0.0f, 0.3f}) {
    TraceStats stats;
    const Image image = tracer.trace(s, spot_down(3.0f, size), 16, {}, &stats);
    EXPECT_EQ(stats.untraceable, static_cast<long>(bad.size()));
    for (std::size_t b = 0; b < bad.size(); ++b) {
      const int x = static_cast<int>(3 * b);
      EXPECT_EQ(image.pixel(x, 0)[0], 0.0f) << "case " << b << ", size " << size;
      EXPECT_EQ(image.pixel(x + 1, 0)[0], 1.0f) << "case " << b << ", size " << size;
      EXPECT_EQ(image.pixel(x + 1, 0)[3], 1.0f) << "case " << b << ", size " << size;
      EXPECT_EQ(image.pixel(x + 2, 0)[3], 0.0f) << "case " << b << " is judged, size " << size;
      EXPECT_EQ(image.pixel(x + 2, 0)[0], 0.0f) << "case " << b << ", size " << size;
    }
  }
}

// Rays travel in packets of 16 that mix pixels and rows: every pixel gets
// its own rays' answers. Three rows of 37 points (some uncovered) under a
// half-plane x < 0 at height 1, lit from 3 above the origin: with a point
// light a point is shadowed exactly where x < 0; with a square 0.2 wide
// and 7 rays per pixel (packets straddle pixels) the penumbra is 0.05 on
// either side, so every point here is exactly lit or exactly shadowed.
// Each covered point above the horizon traces one ray per sample.
TEST(ShadowRayTracer, PacketsGiveEachPixelItsOwnRays) {
  TriangleMesh mesh;
  add_quad(mesh, -5.0f, 0.0f, -2.5f, 2.5f, 1.0f);
  const ShadowRayTracer tracer(mesh);
  constexpr int kColumns = 37, kRows = 3;
  SurfacePoints s(kColumns, kRows);
  long covered = 0;
  for (int y = 0; y < kRows; ++y) {
    for (int x = 0; x < kColumns; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kColumns + x;
      s.position[i] = {-1.85f + 0.1f * static_cast<float>(x), 0.0f, 0.3f * (y - 1)};
      s.normal[i] = {0.0f, 1.0f, 0.0f};
      s.covered[i] = (x + 2 * y) % 5 != 0;
      covered += s.covered[i];
    }
  }
  for (const auto& [size, samples] : {std::pair{0.0f, 1}, std::pair{0.2f, 7}}) {
    TraceStats stats;
    const Image image = tracer.trace(s, spot_down(3.0f, size), samples, {}, &stats);
    EXPECT_EQ(stats.rays, covered * samples) << "light size " << size;
    for (int y = 0; y < kRows; ++y) {
      for (int x = 0; x < kColumns; ++x) {
        const float* v = image.pixel(x, y);
        const std::size_t i = static_cast<std::size_t>(y) * kColumns + x;
        if (!s.covered[i]) {
          EXPECT_EQ(v[0], 1.0f);
          EXPECT_EQ(v[3], 0.0f);
          continue;
        }
        EXPECT_EQ(v[0], s.position[i].x < 0.0f ? 0.0f : 1.0f)
            << "light size " << size << ", point " << x << ", " << y;
        EXPECT_EQ(v[3], 1.0f);
      }
    }
  }
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
