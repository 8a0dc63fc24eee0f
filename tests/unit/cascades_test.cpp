// Cascaded shadow views of a directional light: the split scheme, the
// slice spheres, texel snapping and the stability it buys.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "penumbra/shadow/cascades.hpp"
#include "scene/mesh.hpp"

namespace penumbra {
namespace {

TEST(Cascades, SplitsFollowThePracticalSchemeAndIncrease) {
  const float n = 0.5f, f = 80.0f;
  for (int count = 1; count <= 4; ++count) {
    for (float lambda : {0.0f, 0.5f, 0.75f, 1.0f}) {
      const std::vector<float> s = cascade_splits(n, f, count, lambda);
      ASSERT_EQ(s.size(), static_cast<std::size_t>(count) + 1);
      EXPECT_EQ(s.front(), n);
      EXPECT_EQ(s.back(), f);
      for (int i = 1; i <= count; ++i) {
        EXPECT_GT(s[static_cast<std::size_t>(i)], s[static_cast<std::size_t>(i) - 1]);
        const double k = double(i) / count;
        const double expected =
            lambda * n * std::pow(double(f) / n, k) + (1.0 - lambda) * (n + (double(f) - n) * k);
        EXPECT_NEAR(s[static_cast<std::size_t>(i)], expected, 1e-4 * f);
      }
    }
  }
  // lambda 0: uniform; lambda 1: logarithmic (each split the geometric mean).
  EXPECT_NEAR(cascade_splits(1.0f, 9.0f, 2, 0.0f)[1], 5.0f, 1e-5f);
  EXPECT_NEAR(cascade_splits(1.0f, 9.0f, 2, 1.0f)[1], 3.0f, 1e-5f);
}

CameraFrustum test_camera(const glm::vec3& position, const glm::vec3& forward) {
  CameraFrustum c;
  c.position = position;
  c.forward = glm::normalize(forward);
  c.fov_y = glm::radians(45.0f);
  c.aspect = 1.6f;
  c.near_plane = 0.3f;
  c.far_plane = 40.0f;
  return c;
}

// The eight corners of the slice [d0, d1] of the camera's frustum.
std::vector<glm::vec3> slice_corners(const CameraFrustum& c, float d0, float d1) {
  const glm::mat4 view = glm::lookAt(c.position, c.position + c.forward, glm::vec3(0, 1, 0));
  const glm::mat4 inverse = glm::inverse(view);
  const float ky = std::tan(0.5f * c.fov_y), kx = ky * c.aspect;
  std::vector<glm::vec3> corners;
  for (float d : {d0, d1})
    for (float sx : {-1.0f, 1.0f})
      for (float sy : {-1.0f, 1.0f})
        corners.emplace_back(inverse * glm::vec4(sx * kx * d, sy * ky * d, -d, 1.0f));
  return corners;
}

TEST(Cascades, SliceSphereHoldsTheSliceWhateverTheCameraLooksAt) {
  const CameraFrustum a = test_camera({1, 2, 3}, {0.2f, -0.3f, -1.0f});
  const CameraFrustum b = test_camera({1, 2, 3}, {-0.9f, 0.1f, 0.4f});
  for (auto [d0, d1] : {std::pair{0.3f, 2.0f}, std::pair{2.0f, 9.0f}, std::pair{9.0f, 40.0f}}) {
    const Sphere sa = frustum_slice_sphere(a, d0, d1), sb = frustum_slice_sphere(b, d0, d1);
    EXPECT_FLOAT_EQ(sa.radius, sb.radius) << "the radius must not depend on the orientation";
    for (const glm::vec3& corner : slice_corners(a, d0, d1)) {
      EXPECT_LE(glm::length(corner - sa.center), sa.radius * (1.0f + 1e-5f));
    }
  }
}

TEST(Cascades, SnappingRoundsToWholeTexelsAndRadiiToASparseGrid) {
  const glm::vec2 p = snap_to_texel({1.26f, -0.74f}, 0.5f);
  EXPECT_FLOAT_EQ(p.x, 1.5f);
  EXPECT_FLOAT_EQ(p.y, -0.5f);
  for (float r : {0.37f, 1.05f, 3.3f, 17.0f}) {
    const float q = quantize_cascade_radius(r);
    EXPECT_GE(q, r);
    EXPECT_LT(q, r * 1.0906f);  // 2^(1/8)
    EXPECT_FLOAT_EQ(quantize_cascade_radius(r * 1.001f), quantize_cascade_radius(r))
        << "nearby radii share a step (unless one sits at a step's edge)";
  }
}

Light sun() {
  Light light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(glm::vec3(0.7f, -1.0f, -0.25f));
  return light;
}

std::vector<Vertex> ground_vertices(float half = 20.0f, float tilt = 3.0f) {
  std::vector<Vertex> v(4);
  v[0].position = {-half, 0, -half};
  v[1].position = {half, 0, -half};
  v[2].position = {half, tilt, half};
  v[3].position = {-half, 0, half};
  return v;
}

const std::vector<std::uint32_t> kQuad = {0, 1, 2, 0, 2, 3};

TEST(Cascades, EveryCascadeHoldsItsSlice) {
  const CameraFrustum camera = test_camera({0, 6, 10}, {0, -0.5f, -1});
  const std::vector<float> splits = cascade_splits(camera.near_plane, camera.far_plane, 4, 0.75f);
  const float blend = 0.3f;
  const std::vector<LightView> views =
      fit_cascade_views(sun(), camera, splits, blend, ground_vertices(), kQuad, 512);
  ASSERT_EQ(views.size(), 4u);
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (i > 0) {
      EXPECT_GT(views[i].texel_world, views[i - 1].texel_world);
    }
    // The slice includes the blend band of the cascade before, where
    // points read this cascade too.
    const float start = cascade_slice_start(splits, blend, i);
    if (i > 0) {
      EXPECT_NEAR(start, splits[i] - blend * (splits[i] - splits[i - 1]), 1e-5f);
    }
    for (const glm::vec3& corner : slice_corners(camera, start, splits[i + 1])) {
      const glm::vec4 clip = views[i].view_projection * glm::vec4(corner, 1.0f);
      ASSERT_LE(std::abs(clip.x), 1.0f) << "cascade " << i;
      ASSERT_LE(std::abs(clip.y), 1.0f) << "cascade " << i;
    }
  }
}

TEST(Cascades, SubTexelCameraMovesShiftTheMapsByWholeTexels) {
  const int size = 512;
  const CameraFrustum before = test_camera({0, 6, 10}, {0, -0.5f, -1});
  const std::vector<float> splits = cascade_splits(0.3f, 40.0f, 3, 0.75f);
  for (const bool tight : {false, true}) {
    const std::vector<LightView> a =
        fit_cascade_views(sun(), before, splits, 0.1f, ground_vertices(), kQuad, size, tight);
    for (const glm::vec3& move :
         {glm::vec3(0.003f, 0, 0), glm::vec3(0, 0.002f, -0.004f), glm::vec3(0.05f, 0.01f, 0.02f)}) {
      CameraFrustum after = before;
      after.position += move;
      // A turn of the camera too, but for the tight fit: the sphere does
      // not follow orientation.
      if (!tight) after.forward = glm::normalize(before.forward + glm::vec3(0.01f, 0.0f, 0.0f));
      const std::vector<LightView> b =
          fit_cascade_views(sun(), after, splits, 0.1f, ground_vertices(), kQuad, size, tight);
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_FLOAT_EQ(a[i].texel_world, b[i].texel_world);
        // The depth bounds are snapped too: the stored depths do not change.
        EXPECT_EQ(a[i].z0, b[i].z0) << "cascade " << i;
        EXPECT_EQ(a[i].z1, b[i].z1) << "cascade " << i;
        // The map's origin, in texels of light space: whole-texel shifts only.
        const glm::vec4 origin_a = glm::inverse(a[i].view_projection) * glm::vec4(-1, -1, 0, 1);
        const glm::vec4 origin_b = glm::inverse(b[i].view_projection) * glm::vec4(-1, -1, 0, 1);
        const glm::vec2 la = glm::vec2(a[i].view * origin_a), lb = glm::vec2(b[i].view * origin_b);
        const glm::vec2 shift = (lb - la) / a[i].texel_world;
        EXPECT_NEAR(shift.x, std::round(shift.x), 1e-2f) << "cascade " << i;
        EXPECT_NEAR(shift.y, std::round(shift.y), 1e-2f) << "cascade " << i;
      }
    }
  }
}

// Tight, fitted to their receivers, the cascades' texels are finer than the
// slices' spheres give, and each map holds every receiver with the reach
// of its blockers through the sun's disc around it: a ground seen from
// under a roof 8 units above it, whose every point the roof can shadow
// from up to tan(angle / 2) times its height off the point's column.
TEST(Cascades, TightCascadesHoldTheirReceiversAndTheirBlockersReach) {
  const CameraFrustum camera = test_camera({0, 3, 10}, {0, -0.5f, -1});
  const std::vector<float> splits = cascade_splits(camera.near_plane, camera.far_plane, 3, 0.75f);
  const float blend = 0.1f, roof = 8.0f;
  std::vector<Vertex> vertices = ground_vertices(20.0f, 0.0f);
  for (const Vertex& v : ground_vertices(60.0f, 0.0f)) {
    vertices.push_back(v);
    vertices.back().position.y = roof;
  }
  std::vector<std::uint32_t> indices = kQuad;
  for (std::uint32_t k : kQuad) indices.push_back(k + 4);
  const glm::mat4 camera_view =
      glm::lookAt(camera.position, camera.position + camera.forward, glm::vec3(0, 1, 0));
  const float ky = std::tan(0.5f * camera.fov_y), kx = ky * camera.aspect;
  // (The smallest maps keep a margin of an eighth of their width.)
  for (const auto& [angle, size] :
       {std::pair{0.5f, 512}, std::pair{10.0f, 512}, std::pair{0.5f, 16}}) {
    Light light = sun();
    light.sun_angle = angle;
    const std::vector<LightView> fitted =
        fit_cascade_views(light, camera, splits, blend, vertices, indices, size, true);
    const std::vector<LightView> stable =
        fit_cascade_views(light, camera, splits, blend, vertices, indices, size);
    ASSERT_EQ(fitted.size(), 3u);
    // The roof's height above the ground in light depth, and the reach.
    const float height = roof / -glm::normalize(light.direction).y;
    const float reach = std::tan(0.5f * glm::radians(angle)) * height;
    const glm::mat4 light_frame = cascade_light_frame(light);
    const glm::vec3 light_x = glm::vec3(glm::row(light_frame, 0));
    const glm::vec3 light_y = glm::vec3(glm::row(light_frame, 1));
    for (std::size_t i = 0; i < fitted.size(); ++i) {
      // (A wide sun's reach may make a small slice's square the larger.)
      EXPECT_GT(fitted[i].texel_world, 0.0f);
      if (angle < 1.0f && size == 512) {
        EXPECT_LT(fitted[i].texel_world, 0.8f * stable[i].texel_world) << "cascade " << i;
      }
      const float d0 = cascade_slice_start(splits, blend, i), d1 = splits[i + 1];
      int receivers = 0;
      for (float x = -20.0f; x <= 20.0f; x += 0.125f) {
        for (float z = -20.0f; z <= 20.0f; z += 0.125f) {
          const glm::vec3 p(x, 0.0f, z);
          const glm::vec3 e = glm::vec3(camera_view * glm::vec4(p, 1.0f));
          const float depth = -e.z;
          if (depth < d0 || depth > d1 || std::abs(e.x) > kx * depth ||
              std::abs(e.y) > ky * depth) {
            continue;
          }
          ++receivers;
          for (const glm::vec3& off :
               {reach * light_x, -reach * light_x, reach * light_y, -reach * light_y}) {
            const glm::vec4 clip = fitted[i].view_projection * glm::vec4(p + off, 1.0f);
            ASSERT_LE(std::abs(clip.x), 1.0f)
                << "cascade " << i << ", angle " << angle << ", " << size << " texels";
            ASSERT_LE(std::abs(clip.y), 1.0f)
                << "cascade " << i << ", angle " << angle << ", " << size << " texels";
          }
        }
      }
      EXPECT_GT(receivers, 100) << "cascade " << i;
    }
  }
}

// Each cascade's depth bounds come from the geometry in its own column:
// the ground beyond the camera's view does not widen them, a caster above
// the column lowers the near end, one beside the column does not.
TEST(Cascades, DepthBoundsFollowTheCascadeNotTheScene) {
  const CameraFrustum camera = test_camera({0, 6, 10}, {0, -0.5f, -1});
  const std::vector<float> splits = cascade_splits(camera.near_plane, camera.far_plane, 3, 0.75f);
  const std::vector<LightView> small =
      fit_cascade_views(sun(), camera, splits, 0.1f, ground_vertices(100.0f, 0.0f), kQuad, 512);
  const std::vector<LightView> large =
      fit_cascade_views(sun(), camera, splits, 0.1f, ground_vertices(1600.0f, 0.0f), kQuad, 512);
  for (std::size_t i = 0; i < small.size(); ++i) {
    EXPECT_EQ(small[i].z0, large[i].z0) << "cascade " << i;
    EXPECT_EQ(small[i].z1, large[i].z1) << "cascade " << i;
    // A flat ground seen under the sun spans the column's width times the
    // slope of the light: far less than the 1600-unit ground does.
    const float width = small[i].texel_world * 512.0f;
    EXPECT_LT(small[i].z1 - small[i].z0, 2.5f * width) << "cascade " << i;
  }
  // A small caster 30 units towards the sun from a ground point that the
  // second cascade shades (camera depth 7.6).
  const glm::vec3 ground(0.0f, 0.0f, 4.5f);
  const glm::vec3 caster = ground - 30.0f * sun().direction;
  std::vector<Vertex> vertices = ground_vertices(1600.0f, 0.0f);
  for (const glm::vec3& offset :
       {glm::vec3(0.0f), glm::vec3(0.1f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 0.1f)}) {
    Vertex v;
    v.position = caster + offset;
    vertices.push_back(v);
  }
  std::vector<std::uint32_t> indices = kQuad;
  for (std::uint32_t k : {4u, 5u, 6u}) indices.push_back(k);
  const std::vector<LightView> with_caster =
      fit_cascade_views(sun(), camera, splits, 0.1f, vertices, indices, 512);
  EXPECT_LT(with_caster[1].z0, small[1].z0);
  EXPECT_GE(with_caster[1].relative_depth(caster), 0.0f);
  EXPECT_LT(with_caster[1].relative_depth(caster), 0.1f) << "the caster is the nearest geometry";
  EXPECT_LT(with_caster[1].relative_depth(ground), 1.0f) << "the receiver is inside";
  EXPECT_GT(with_caster[1].z1 - with_caster[1].z0, small[1].z1 - small[1].z0);
  // Moved far off to the side, the caster is in no cascade's column.
  for (std::uint32_t k : {4u, 5u, 6u}) vertices[k].position.x += 300.0f;
  const std::vector<LightView> beside =
      fit_cascade_views(sun(), camera, splits, 0.1f, vertices, indices, 512);
  for (std::size_t i = 0; i < small.size(); ++i) {
    EXPECT_EQ(beside[i].z0, small[i].z0) << "cascade " << i;
  }
}

}  // namespace
}  // namespace penumbra
