// The traced reference must not depend on the CPU it runs on. Embree picks
// its kernels by instruction set, and only AVX-512 has a native 16-wide
// packet kernel: on AVX2 and SSE4.2 it traces rtcIntersect16 and
// rtcOccluded16 through a fallback that takes every lane whose tnear <=
// tfar as active, whatever the valid mask says (shadow_ray_tracer.cpp). So
// each scene here, chosen to leave packets partly filled (background
// beside silhouettes, a model floating above a small ground, a grazing
// plane, a point light), is traced with Embree's kernels forced to each
// instruction set this CPU has (PENUMBRA_EMBREE_CONFIG), and the
// references must agree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "gpu_fixture.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// The instruction sets Embree can be forced to on this CPU (its "isa="
// names), the widest last. Embree's AVX-512 kernels need the Skylake
// server subset.
std::vector<std::string> supported_isas() {
  std::vector<std::string> isas;
  if (__builtin_cpu_supports("sse4.2")) isas.emplace_back("sse4.2");
  if (__builtin_cpu_supports("avx2")) isas.emplace_back("avx2");
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl")) {
    isas.emplace_back("avx512");
  }
  return isas;
}

// Sets PENUMBRA_EMBREE_CONFIG while it lives; restores what was there.
class EmbreeConfig {
 public:
  explicit EmbreeConfig(const std::string& config) {
    if (const char* old = std::getenv(kName)) previous_ = old;
    ::setenv(kName, config.c_str(), 1);
  }
  ~EmbreeConfig() {
    if (previous_) {
      ::setenv(kName, previous_->c_str(), 1);
    } else {
      ::unsetenv(kName);
    }
  }
  EmbreeConfig(const EmbreeConfig&) = delete;
  EmbreeConfig& operator=(const EmbreeConfig&) = delete;

 private:
  static constexpr const char* kName = "PENUMBRA_EMBREE_CONFIG";
  std::optional<std::string> previous_;
};

Shape plane(float size) {
  Shape s;
  s.kind = ShapeKind::Plane;
  s.size = {size, 0.0f, size};
  return s;
}

Shape sphere(glm::vec3 center, float radius) {
  Shape s;
  s.kind = ShapeKind::Sphere;
  s.position = center;
  s.radius = radius;
  return s;
}

Shape box(glm::vec3 center, glm::vec3 size, float yaw_degrees = 0.0f) {
  Shape s;
  s.kind = ShapeKind::Box;
  s.position = center;
  s.size = size;
  s.rotation_degrees = {0.0f, yaw_degrees, 0.0f};
  return s;
}

Light light_at(LightType type, glm::vec3 position, glm::vec3 direction) {
  Light l;
  l.type = type;
  l.position = position;
  l.direction = glm::normalize(direction);
  l.cone_degrees = 50.0f;
  l.inner_cone_degrees = 40.0f;
  return l;
}

struct IsaScene {
  const char* name;
  Scene scene;
  float light_size;
};

Scene with(std::vector<Shape> shapes, glm::vec3 eye, glm::vec3 target, Light light) {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.shapes = std::move(shapes);
  scene.camera.position = eye;
  scene.camera.target = target;
  scene.lights.push_back(light);
  return scene;
}

std::vector<IsaScene> isa_scenes() {
  std::vector<IsaScene> scenes;
  // Sky beside the silhouettes of a box and a sphere on a ground that ends
  // inside the view.
  scenes.push_back({"background beside silhouettes",
                    with({plane(6.0f), box({-0.8f, 0.5f, 0.0f}, glm::vec3(1.0f), 30.0f),
                          sphere({0.9f, 0.6f, 0.3f}, 0.6f)},
                         {0.0f, 1.2f, 6.0f}, {0.0f, 0.8f, 0.0f},
                         light_at(LightType::Spot, {2.0f, 5.0f, 3.0f}, {-2.0f, -5.0f, -3.0f})),
                    0.8f});
  // A smooth sphere (its rays start on the smooth surface) floating above
  // a ground smaller than the view.
  scenes.push_back(
      {"model floating above a small ground",
       with({plane(2.0f), sphere({0.0f, 1.2f, 0.0f}, 0.5f)}, {0.0f, 2.5f, 4.5f}, {0.0f, 0.6f, 0.0f},
            light_at(LightType::Spot, {0.5f, 4.0f, 0.5f}, {-0.5f, -4.0f, -0.5f})),
       0.6f});
  // The sun a few degrees above the ground's plane.
  scenes.push_back(
      {"grazing plane",
       with({plane(8.0f), box({0.0f, 0.3f, 0.0f}, {0.6f, 0.6f, 0.6f}, 20.0f)}, {0.0f, 3.0f, 5.0f},
            {0.0f, 0.0f, 0.0f},
            light_at(LightType::Directional, {0.0f, 0.0f, 0.0f}, {-1.0f, -0.08f, -0.3f})),
       0.0f});
  // A point light with a spherical source, above and beside the box.
  scenes.push_back({"point light",
                    with({plane(5.0f), box({0.0f, 0.4f, 0.0f}, {0.8f, 0.8f, 0.8f}, 10.0f),
                          sphere({1.2f, 0.3f, -0.5f}, 0.3f)},
                         {1.0f, 2.0f, 4.0f}, {0.0f, 0.3f, 0.0f},
                         light_at(LightType::Point, {-0.5f, 2.5f, 0.8f}, {0.0f, -1.0f, 0.0f})),
                    0.5f});
  return scenes;
}

TEST_F(GpuTest, TracedReferenceAgreesAcrossEmbreeInstructionSets) {
  const std::vector<std::string> isas = supported_isas();
  ASSERT_FALSE(isas.empty()) << "no instruction set Embree supports";
  constexpr int kSamples = 16;
  for (const IsaScene& test : isa_scenes()) {
    Renderer renderer(test.scene);
    RenderSettings view = testing::small_frame(96, 54);
    ShadowSettings settings;
    settings.technique = Technique::None;
    settings.map_size = 256;
    settings.light_size = test.light_size;
    settings.sun_angle = 2.0f;
    renderer.render(view, settings);
    const SurfacePoints surfaces = renderer.read_surfaces();
    const long covered = std::count(surfaces.covered.begin(), surfaces.covered.end(), 1);
    ASSERT_GT(covered, 0) << test.name;
    ASSERT_LT(covered, static_cast<long>(surfaces.size())) << test.name << ": no background";
    const ReferenceLight light =
        make_reference_light(renderer.scene().lights[0], renderer.light_view(0), settings);

    std::vector<Image> images;
    for (const std::string& isa : isas) {
      const EmbreeConfig config("isa=" + isa);
      const ShadowRayTracer tracer(renderer.mesh(), renderer.scene().materials);
      images.push_back(tracer.trace(surfaces, light, kSamples));
    }
    long judged = 0, shadowed = 0;
    for (std::size_t i = 3; i < images[0].rgba.size(); i += 4) {
      judged += images[0].rgba[i] > 0.5f;
      shadowed += images[0].rgba[i] > 0.5f && images[0].rgba[i - 3] < 0.5f;
    }
    EXPECT_GT(judged, covered / 2) << test.name;
    EXPECT_GT(shadowed, 0) << test.name << ": no shadow to compare";
    for (std::size_t k = 1; k < images.size(); ++k) {
      // The same rays through another BVH and another triangle test: at
      // most a ray that grazes an edge may differ.
      long differ = 0;
      double worst = 0.0;
      for (std::size_t i = 0; i < images[0].rgba.size(); ++i) {
        const double d = std::abs(double(images[0].rgba[i]) - images[k].rgba[i]);
        worst = std::max(worst, d);
        differ += d > 1e-5;
      }
      std::printf("%s: %s against %s: %ld values differ, by up to %.4f\n", test.name,
                  isas[k].c_str(), isas[0].c_str(), differ, worst);
      EXPECT_LE(differ, static_cast<long>(surfaces.size()) / 200)
          << test.name << ": " << isas[k] << " against " << isas[0];
      EXPECT_LE(worst, 2.0 / kSamples) << test.name << ": " << isas[k] << " against " << isas[0];
    }
  }
}

}  // namespace
}  // namespace penumbra
