// Screen-space ambient occlusion on known geometry: a plane alone, a box and
// a sphere resting on it, a sphere floating above it; the raw AO against a
// CPU evaluation of seed 003's estimator on the same G-buffer.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <vector>

#include "gpu_fixture.hpp"
#include "io/image.hpp"
#include "render/camera_depth.hpp"
#include "render/renderer.hpp"
#include "render/ssao_kernel.hpp"
#include "scene/builtin_scenes.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kWidth = 256;
constexpr int kHeight = 192;

Scene plane_scene(glm::vec3 camera, glm::vec3 target, glm::vec3 up = {0.0f, 1.0f, 0.0f}) {
  Scene scene = testing::TestScene("ssao test")
                    .ground(40.0f)
                    .camera(camera, target, 45.0f)
                    .light(testing::sun_light({0.0f, -1.0f, 0.0f}));
  scene.camera.up = up;
  return scene;
}

void add_box(Scene& scene, glm::vec3 center, float size) {
  Shape box;
  box.kind = ShapeKind::Box;
  box.size = glm::vec3(size);
  box.position = center;
  scene.shapes.push_back(box);
}

void add_sphere(Scene& scene, glm::vec3 center, float radius) {
  Shape sphere;
  sphere.kind = ShapeKind::Sphere;
  sphere.position = center;
  sphere.radius = radius;
  scene.shapes.push_back(sphere);
}

RenderSettings ao_view(int width = kWidth, int height = kHeight) {
  RenderSettings rs = testing::small_frame(width, height, View::Ao);
  return rs;
}

ShadowSettings no_shadow() {
  ShadowSettings shadow;
  shadow.technique = Technique::None;
  shadow.map_size = 64;
  return shadow;
}

// Writes an AO image under the test output folder, for looking at.
void save(const Image& image, const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(PENUMBRA_TEST_OUTPUT) / "ssao";
  std::filesystem::create_directories(dir);
  write_png(image, (dir / (name + ".png")).string(), PngEncoding::Linear);
}

Image render_ao(Renderer& renderer, const SsaoSettings& ssao, int width = kWidth,
                int height = kHeight) {
  renderer.render(ao_view(width, height), no_shadow(), ssao);
  return renderer.read_view();
}

struct Ray {
  glm::vec3 origin, direction;
};

// The camera ray through the centre of image pixel (x, y), rows top to bottom.
Ray pixel_ray(const Renderer& r, int width, int height, int x, int y) {
  const glm::dmat4 inverse =
      glm::inverse(glm::dmat4(r.camera_projection(width, height) * r.camera_view()));
  const glm::dvec2 ndc{(x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0};
  const glm::vec3 origin(position_from_depth(inverse, ndc, CAMERA_NEAR_DEPTH));
  const glm::vec3 far_point(position_from_depth(inverse, ndc, CAMERA_FAR_DEPTH));
  return {origin, glm::normalize(far_point - origin)};
}

std::optional<float> hit_sphere(const Ray& ray, glm::vec3 center, float radius) {
  glm::vec3 oc = ray.origin - center;
  float b = glm::dot(oc, ray.direction), c = glm::dot(oc, oc) - radius * radius;
  float disc = b * b - c;
  if (disc < 0.0f) return std::nullopt;
  return -b - std::sqrt(disc);
}

std::optional<float> hit_box(const Ray& ray, glm::vec3 lo, glm::vec3 hi) {
  glm::vec3 t0 = (lo - ray.origin) / ray.direction, t1 = (hi - ray.origin) / ray.direction;
  glm::vec3 tmin = glm::min(t0, t1), tmax = glm::max(t0, t1);
  float enter = std::max({tmin.x, tmin.y, tmin.z}), leave = std::min({tmax.x, tmax.y, tmax.z});
  if (enter > leave || leave < 0.0f) return std::nullopt;
  return enter;
}

// Where the ray meets the ground y = 0, if nothing else is nearer. Objects
// are inflated by `margin` so that pixels grazing a faceted silhouette do
// not count as ground.
struct Occluders {
  std::vector<std::pair<glm::vec3, float>> spheres;    // centre, radius
  std::vector<std::pair<glm::vec3, glm::vec3>> boxes;  // min, max
};

std::optional<glm::vec3> ground_point(const Ray& ray, const Occluders& objects,
                                      float margin = 0.02f) {
  if (ray.direction.y >= 0.0f) return std::nullopt;
  float t = -ray.origin.y / ray.direction.y;
  for (auto [c, r] : objects.spheres) {
    if (auto s = hit_sphere(ray, c, r + margin); s && *s < t) return std::nullopt;
  }
  for (auto [lo, hi] : objects.boxes) {
    if (auto s = hit_box(ray, lo - margin, hi + margin); s && *s < t) return std::nullopt;
  }
  return ray.origin + t * ray.direction;
}

struct Mean {
  double sum = 0.0;
  int count = 0;
  float min = 1e30f;
  void add(float v) {
    sum += v;
    ++count;
    min = std::min(min, v);
  }
  [[nodiscard]] double value() const { return count ? sum / count : 0.0; }
};

bool all_finite(const Image& image) {
  return std::all_of(image.rgba.begin(), image.rgba.end(),
                     [](float v) { return std::isfinite(v); });
}

// A plane seen head-on has nothing in its hemisphere: every sample must
// count as unoccluded, so any darkening is self-occlusion from the depth
// test (a depth bias too small for the depth buffer's error).
TEST_F(GpuTest, SsaoFlatPlaneFacingTheCameraIsUnoccluded) {
  Renderer renderer(plane_scene({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}));
  for (bool half : {false, true}) {
    SsaoSettings ssao;
    ssao.half_resolution = half;
    Image ao = render_ao(renderer, ssao);
    save(ao, half ? "plane-half" : "plane");
    ASSERT_TRUE(all_finite(ao));
    Mean m;
    for (int y = 0; y < ao.height; ++y)
      for (int x = 0; x < ao.width; ++x) m.add(ao.pixel(x, y)[0]);
    std::printf("plane facing the camera%s: AO min %.4f, mean %.4f\n", half ? " (half res)" : "",
                m.min, m.value());
    EXPECT_EQ(m.count, kWidth * kHeight);
    EXPECT_GE(m.min, 0.98f) << "self-occlusion on an open plane";
  }
}

// Fraction of the pixels where geometry was seen whose AO is below `limit`.
double acne(const Image& ao, float limit) {
  int seen = 0, darkened = 0;
  for (int y = 0; y < ao.height; ++y) {
    for (int x = 0; x < ao.width; ++x) {
      if (ao.pixel(x, y)[3] == 0.0f) continue;  // background
      ++seen;
      darkened += ao.pixel(x, y)[0] < limit;
    }
  }
  return seen ? double(darkened) / seen : 0.0;
}

// Surfaces with nothing in their hemisphere, where self-occlusion shows
// most: a plane seen at 3 to 30 degrees (the depth read at a texel's
// centre differs there from the depth along a sample's own ray by more
// than the lower samples' height), and a lone sphere and box, convex and
// tessellated (the interpolated normals lean over the facets). Unblurred,
// so that no acne is averaged away.
TEST_F(GpuTest, SsaoUnoccludedSurfacesHaveNoAcne) {
  Scene grazing = plane_scene({0.0f, 2.5f, 22.0f}, {0.0f, 0.0f, 4.0f});
  // Inside the scene's bounds the near plane falls to 1e-4 of the far one.
  Scene inside = plane_scene({0.0f, 1.5f, 8.0f}, {0.0f, 0.0f, 0.0f});
  // More than r apart: neither occludes the other.
  Scene convex = plane_scene({0.0f, 1.0f, 8.0f}, {0.0f, 0.5f, 0.0f});
  convex.shapes.clear();
  add_sphere(convex, {-1.8f, 0.5f, 0.0f}, 0.8f);
  add_box(convex, {1.8f, 0.5f, 0.0f}, 1.0f);
  convex.shapes.back().rotation_degrees = {20.0f, 35.0f, 0.0f};
  std::vector<double> faint_acne;  // per scene: default bias, then none
  for (const Scene* scene : {&grazing, &inside, &convex}) {
    Renderer renderer(*scene);
    for (float bias : {SsaoSettings{}.bias, 0.0f}) {
      SsaoSettings ssao;
      ssao.bias = bias;
      ssao.blur = 0;
      Image ao = render_ao(renderer, ssao);
      const std::string name = scene == &grazing  ? "grazing-plane"
                               : scene == &inside ? "grazing-plane-inside"
                                                  : "convex";
      save(ao, name + (bias > 0.0f ? "" : "-no-bias"));
      const double a = acne(ao, 0.98f), faint = acne(ao, 0.999f);
      std::printf("%s, bias %.3f, no blur: %.3f%% of the pixels below 0.98, %.3f%% below 0.999\n",
                  name.c_str(), bias, 100.0 * a, 100.0 * faint);
      faint_acne.push_back(faint);
      if (bias > 0.0f) {
        EXPECT_LT(a, 0.001) << name;
      }
    }
  }
  // Planes are exact; on the tessellated objects the bias removes part of
  // the faint self-occlusion (isolated pixels a few percent below 1).
  EXPECT_EQ(faint_acne[0] + faint_acne[1] + faint_acne[2] + faint_acne[3], 0.0);
  EXPECT_LT(faint_acne[4], faint_acne[5]);
}

// The ground's AO by distance d from a box's foot or a sphere's contact.
struct Profile {
  Mean near, far;
};

Profile ground_profile(const Renderer& renderer, const Image& ao, const Occluders& objects,
                       auto distance, float near_lo, float near_hi, float far_lo, float far_hi) {
  Profile profile;
  for (int y = 0; y < ao.height; ++y) {
    for (int x = 0; x < ao.width; ++x) {
      auto p = ground_point(pixel_ray(renderer, ao.width, ao.height, x, y), objects);
      if (!p) continue;
      const float d = distance(*p);
      if (d >= near_lo && d <= near_hi) profile.near.add(ao.pixel(x, y)[0]);
      if (d >= far_lo && d <= far_hi) profile.far.add(ao.pixel(x, y)[0]);
    }
  }
  return profile;
}

TEST_F(GpuTest, SsaoBoxFootIsDarkerThanOpenGround) {
  Scene scene = plane_scene({3.0f, 2.5f, 4.0f}, {0.0f, 0.3f, 0.0f});
  add_box(scene, {0.0f, 0.5f, 0.0f}, 1.0f);
  Renderer renderer(scene);
  const Occluders objects{{}, {{glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f)}}};
  // Distance from the box's footprint, the square |x|, |z| <= 0.5.
  auto from_box = [](glm::vec3 p) {
    glm::vec2 outside = glm::max(glm::abs(glm::vec2(p.x, p.z)) - 0.5f, 0.0f);
    return glm::length(outside);
  };
  for (bool half : {false, true}) {
    SsaoSettings ssao;
    ssao.half_resolution = half;
    Image ao = render_ao(renderer, ssao);
    save(ao, half ? "box-half" : "box");
    Profile p = ground_profile(renderer, ao, objects, from_box, 0.0f, 0.1f, 0.95f, 1.05f);
    std::printf("box foot%s: AO within 0.1 m %.3f (%d px), 1 m away %.3f (%d px, min %.3f)\n",
                half ? " (half res)" : "", p.near.value(), p.near.count, p.far.value(), p.far.count,
                p.far.min);
    ASSERT_GT(p.near.count, 100);
    ASSERT_GT(p.far.count, 200);
    // Half resolution loses the texels nearest the crease, where the box
    // covers the G-buffer texel an AO texel is computed at.
    EXPECT_LT(p.near.value(), half ? 0.88 : 0.82);
    EXPECT_GT(p.far.value(), 0.98);
  }
}

TEST_F(GpuTest, SsaoSphereDarkensThePlaneAroundItsContact) {
  Scene scene = plane_scene({0.0f, 2.5f, 4.0f}, {0.0f, 0.3f, 0.0f});
  add_sphere(scene, {0.0f, 0.5f, 0.0f}, 0.5f);
  Renderer renderer(scene);
  const Occluders objects{{{glm::vec3(0.0f, 0.5f, 0.0f), 0.5f}}, {}};
  auto from_contact = [](glm::vec3 p) { return glm::length(glm::vec2(p.x, p.z)); };
  for (bool half : {false, true}) {
    SsaoSettings ssao;
    ssao.half_resolution = half;
    Image ao = render_ao(renderer, ssao);
    save(ao, half ? "sphere-half" : "sphere");
    Profile p = ground_profile(renderer, ao, objects, from_contact, 0.3f, 0.6f, 1.5f, 1.7f);
    std::printf("sphere contact%s: AO 0.3-0.6 m from contact %.3f (%d px), 1.5 m %.3f (%d px)\n",
                half ? " (half res)" : "", p.near.value(), p.near.count, p.far.value(),
                p.far.count);
    ASSERT_GT(p.near.count, 100);
    ASSERT_GT(p.far.count, 200);
    EXPECT_LT(p.near.value(), 0.8);
    EXPECT_GT(p.far.value(), 0.98);
  }
}

// A sphere floating 1.1 m above the ground cannot occlude it within
// r = 0.5, but seen from 35 degrees above it hides the sample points of the
// ground around its silhouette, from about 1.9 m in front of them: the
// seed's range check of 5 r counts them as occluded (a dark halo), the
// default 2 r does not.
TEST_F(GpuTest, SsaoFloatingSphereLeavesNoHaloOnTheGround) {
  Scene scene = plane_scene({0.0f, 5.0f, 5.0f}, {0.0f, 1.0f, 0.0f});
  const glm::vec3 center{0.0f, 1.6f, 0.0f};
  add_sphere(scene, center, 0.5f);
  Renderer renderer(scene);
  const Occluders objects{{{center, 0.5f}}, {}};
  auto from_axis = [](glm::vec3 p) { return glm::length(glm::vec2(p.x, p.z)); };
  for (float range : {SsaoSettings{}.range, 5.0f}) {
    SsaoSettings ssao;
    ssao.radius = 0.5f;
    ssao.range = range;
    Image ao = render_ao(renderer, ssao);
    save(ao, "floating-sphere-range" + std::to_string(static_cast<int>(range)));
    // The ground within 1.1 m of the point under the sphere.
    Profile p = ground_profile(renderer, ao, objects, from_axis, 0.0f, 1.1f, 1.5f, 2.0f);
    std::printf("floating sphere, range %.0f r: ground under it AO mean %.3f, min %.3f (%d px)\n",
                range, p.near.value(), p.near.min, p.near.count);
    ASSERT_GT(p.near.count, 500);
    if (range == SsaoSettings{}.range) {
      EXPECT_GT(p.near.min, 0.98f);
    } else {
      EXPECT_LT(p.near.min, 0.7f) << "expected the seed's range check to leave a halo";
    }
  }
}

// Pixels of mask `a` within `width` pixels (in the max norm) of a pixel of `b`.
std::vector<bool> near_mask(const std::vector<bool>& a, const std::vector<bool>& b, int width,
                            int w, int h) {
  std::vector<bool> out(a.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!a[static_cast<std::size_t>(y * w + x)]) continue;
      for (int dy = -width; dy <= width; ++dy)
        for (int dx = -width; dx <= width; ++dx) {
          int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
          if (b[static_cast<std::size_t>(qy * w + qx)])
            out[static_cast<std::size_t>(y * w + x)] = true;
        }
    }
  return out;
}

double masked_mean(const Image& image, const std::vector<bool>& mask) {
  Mean m;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (mask[static_cast<std::size_t>(y * image.width + x)]) m.add(image.pixel(x, y)[0]);
  return m.value();
}

// A horizontal then vertical Gaussian of radius r (s = r / 2) that ignores
// depth and normals: what the bilateral blur must not do.
Image plain_blur(const Image& in, int r) {
  Image tmp = in, out = in;
  const float s = 0.5f * static_cast<float>(r);
  for (int axis = 0; axis < 2; ++axis) {
    const Image& src = axis == 0 ? in : tmp;
    Image& dst = axis == 0 ? tmp : out;
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x) {
        float sum = 0.0f, weights = 0.0f;
        for (int i = -r; i <= r; ++i) {
          int qx = axis == 0 ? x + i : x, qy = axis == 0 ? y : y + i;
          if (qx < 0 || qy < 0 || qx >= in.width || qy >= in.height) continue;
          float w = std::exp(-float(i * i) / (2.0f * s * s));
          sum += w * src.pixel(qx, qy)[0];
          weights += w;
        }
        dst.pixel(x, y)[0] = sum / weights;
      }
  }
  return out;
}

// A small sphere floating between the camera and the foot of a box: across
// its silhouette the AO jumps from 1 (nothing within 2 r of the sphere) to
// the darkening of the foot behind it. The blur must keep both sides: the
// mean AO of the 4 pixels on either side of that silhouette stays that of
// the unblurred AO (64 samples, so that its noise averages out), where a
// blur that ignores depth moves each side towards the other.
TEST_F(GpuTest, SsaoBlurDoesNotBleedAcrossDepthDiscontinuities) {
  const glm::vec3 camera{3.0f, 2.5f, 4.0f};
  Scene scene = plane_scene(camera, {0.0f, 0.3f, 0.0f});
  add_box(scene, {0.0f, 0.5f, 0.0f}, 1.0f);
  // On the line of sight to the middle of the foot of the box's +x face.
  const glm::vec3 center = camera + 0.45f * (glm::vec3(0.55f, 0.05f, 0.0f) - camera);
  const float radius = 0.15f;
  add_sphere(scene, center, radius);
  Renderer renderer(scene);
  const Occluders box{{}, {{glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f)}}};
  std::vector<bool> sphere(kWidth * kHeight), foot(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Ray ray = pixel_ray(renderer, kWidth, kHeight, x, y);
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      sphere[i] = hit_sphere(ray, center, radius).has_value();
      if (sphere[i]) continue;
      // The ground within 0.2 m of the box, or the box's faces below 0.2 m.
      if (auto g = ground_point(ray, box, 0.0f)) {
        glm::vec2 outside = glm::max(glm::abs(glm::vec2(g->x, g->z)) - 0.5f, 0.0f);
        foot[i] = glm::length(outside) < 0.2f;
      } else if (auto t = hit_box(ray, box.boxes[0].first, box.boxes[0].second)) {
        foot[i] = (ray.origin + *t * ray.direction).y < 0.2f;
      }
    }
  const std::vector<bool> sphere_side = near_mask(sphere, foot, 4, kWidth, kHeight);
  const std::vector<bool> foot_side = near_mask(foot, sphere, 4, kWidth, kHeight);
  ASSERT_GT(std::count(sphere_side.begin(), sphere_side.end(), true), 30);
  ASSERT_GT(std::count(foot_side.begin(), foot_side.end(), true), 30);
  SsaoSettings ssao;
  ssao.radius = 0.5f;  // the sphere is more than range * r from everything
  ssao.samples = 64;
  ssao.blur = 0;
  Image raw = render_ao(renderer, ssao);
  ssao.blur = 4;
  Image blurred = render_ao(renderer, ssao);
  save(raw, "bleeding-raw");
  save(blurred, "bleeding-blurred");
  const Image plain = plain_blur(raw, 4);
  for (const auto& [side, name] :
       {std::pair{&sphere_side, "sphere"}, std::pair{&foot_side, "box foot behind it"}}) {
    const double r = masked_mean(raw, *side), b = masked_mean(blurred, *side),
                 g = masked_mean(plain, *side);
    std::printf(
        "4 px of the %s at the silhouette: unblurred %.4f, bilateral %.4f, plain "
        "Gaussian %.4f\n",
        name, r, b, g);
    EXPECT_NEAR(b, r, 0.008) << name;  // the plain Gaussian: off by 0.017 and 0.021
  }
  EXPECT_LT(masked_mean(raw, foot_side), masked_mean(raw, sphere_side) - 0.1)
      << "the foot behind the sphere must be darker than the sphere";
}

// Half resolution computes a quarter of the AO texels and upsamples them
// along the surfaces: on the default scene it stays close to the full-
// resolution AO everywhere but within a texel or two of edges.
TEST_F(GpuTest, SsaoHalfResolutionFollowsFullResolution) {
  Renderer renderer(*builtin_scene("default"));
  SsaoSettings ssao;
  Image full = render_ao(renderer, ssao);
  ssao.half_resolution = true;
  Image half = render_ao(renderer, ssao);
  save(full, "default");
  save(half, "default-half");
  Mean difference;
  int large = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      if (full.pixel(x, y)[3] == 0.0f) continue;
      const float d = std::abs(full.pixel(x, y)[0] - half.pixel(x, y)[0]);
      difference.add(d);
      large += d > 0.1f;
    }
  std::printf(
      "default scene, half vs full resolution: mean |difference| %.4f, %d of %d pixels "
      "differ by more than 0.1\n",
      difference.value(), large, difference.count);
  EXPECT_LT(difference.value(), 0.01);
  EXPECT_LT(large, difference.count / 200);
}

// No NaN or Inf anywhere, 1 on the background, AO in [0, 1], at odd sizes
// (partial workgroups, a half-resolution texture that does not divide the
// image) and with objects cut by the image's borders.
TEST_F(GpuTest, SsaoIsFiniteAtBordersAndOnTheBackground) {
  Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  Scene close = scene;
  close.camera.position = {-1.2f, 1.4f, 2.6f};  // the box and the sphere cut by the borders
  Renderer close_renderer(close);
  for (Renderer* r : {&renderer, &close_renderer}) {
    for (bool half : {false, true}) {
      for (int samples : {1, 64}) {
        for (int blur : {0, 16}) {
          SsaoSettings ssao;
          ssao.half_resolution = half;
          ssao.samples = samples;
          ssao.blur = blur;
          Image ao = render_ao(*r, ssao, 255, 191);
          ASSERT_TRUE(all_finite(ao)) << "half " << half << " samples " << samples;
          int background = 0;
          for (int y = 0; y < ao.height; ++y) {
            for (int x = 0; x < ao.width; ++x) {
              const float* px = ao.pixel(x, y);
              ASSERT_GE(px[0], 0.0f);
              ASSERT_LE(px[0], 1.0f);
              if (px[3] == 0.0f) {
                ++background;
                ASSERT_EQ(px[0], 1.0f);
              }
            }
          }
          if (r == &renderer) {
            EXPECT_GT(background, 1000);
          }
          RenderSettings final_view = ao_view(255, 191);
          final_view.view = View::Final;
          r->render(final_view, no_shadow(), ssao);
          ASSERT_TRUE(all_finite(r->read_view()));
        }
      }
    }
  }
}

// The G-buffer as the SSAO pass reads it, rows bottom to top.
struct GBufferData {
  int width = 0, height = 0;
  std::vector<float> depth;
  std::vector<glm::vec4> normal;
};

GBufferData read_gbuffer(const GBufferPass& gbuffer) {
  GBufferData g;
  g.width = gbuffer.depth().width();
  g.height = gbuffer.depth().height();
  const std::size_t n = static_cast<std::size_t>(g.width) * g.height;
  g.depth.resize(n);
  g.normal.resize(n);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(gbuffer.depth().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(n * sizeof(float)), g.depth.data());
  glGetTextureImage(gbuffer.normal().id(), 0, GL_RGBA, GL_FLOAT,
                    static_cast<GLsizei>(n * sizeof(glm::vec4)), g.normal.data());
  return g;
}

// Seed 003's estimator, written out again in double precision from the
// G-buffer, with the kernel and the per-pixel noise the shader uses.
class CpuSsao {
 public:
  CpuSsao(const GBufferData& g, const glm::mat4& view, const glm::mat4& projection,
          const SsaoSettings& s)
      : g_(g),
        view_(view),
        projection_(projection),
        inverse_projection_(glm::inverse(glm::dmat4(projection))),
        s_(s),
        kernel_(ssao_kernel(s.samples)) {}

  // Texel (x, y), rows bottom to top.
  [[nodiscard]] double ao(int x, int y) const {
    glm::dvec3 p, n;
    if (!surface(x, y, p, n)) return 1.0;
    const double angle = 2.0 * std::numbers::pi * noise(float(x), float(y));
    const double shift = noise(float(y) + 0.5f, float(x) + 0.5f);
    glm::dvec3 helper = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    glm::dvec3 t0 = glm::normalize(glm::cross(helper, n)), b0 = glm::cross(n, t0);
    glm::dvec3 t = std::cos(angle) * t0 + std::sin(angle) * b0, b = glm::cross(n, t);
    double visible = 0.0, total = 0.0;
    for (const glm::vec4& k : kernel_) {
      glm::dvec3 w = double(k.x) * t + double(k.y) * b + double(k.z) * n;
      double reach = s_.radius * (1.0 - glm::fract(double(k.w) + shift));
      glm::dvec3 q = p + reach * w;
      total += k.z;
      bool hidden = false;
      glm::dvec4 clip = projection_ * glm::dvec4(q, 1.0);
      glm::dvec2 uv = glm::dvec2(clip) / clip.w * 0.5 + 0.5;
      if (clip.w > 0.0 && uv.x >= 0.0 && uv.y >= 0.0 && uv.x < 1.0 && uv.y < 1.0) {
        int sx = std::min(int(uv.x * g_.width), g_.width - 1);
        int sy = std::min(int(uv.y * g_.height), g_.height - 1);
        glm::dvec3 seen, seen_normal;
        if (surface(sx, sy, seen, seen_normal)) {
          // |p'.z| on the seen texel's tangent plane, along the sample's ray.
          double facing = glm::dot(seen_normal, q);
          double seen_depth = std::abs(facing) < 0.02 * glm::length(q)
                                  ? -seen.z
                                  : -q.z * glm::dot(seen_normal, seen) / facing;
          double behind = -q.z - seen_depth;
          hidden = behind > s_.bias && behind <= s_.bias + s_.range * s_.radius;
        }
      }
      if (!hidden) visible += k.z;
    }
    return visible / total;
  }

 private:
  static float noise(float x, float y) {
    return glm::fract(52.9829189f * glm::fract(x * 0.06711056f + y * 0.00583715f));
  }

  bool surface(int x, int y, glm::dvec3& position, glm::dvec3& normal) const {
    const std::size_t i = static_cast<std::size_t>(y) * g_.width + x;
    const glm::vec4 ns = g_.normal[i];
    if (ns.w == 0.0f) return false;
    glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / glm::dvec2(g_.width, g_.height) * 2.0 - 1.0;
    position = position_from_depth(inverse_projection_, ndc, g_.depth[i]);
    normal = glm::normalize(glm::dmat3(view_) * glm::dvec3(ns));
    return true;
  }

  const GBufferData& g_;
  glm::dmat4 view_, projection_, inverse_projection_;
  SsaoSettings s_;
  std::vector<glm::vec4> kernel_;
};

// The unblurred GPU AO against the CPU estimator on the default scene, with
// the default parameters and with others. A pixel may differ where a sample
// lands within rounding of a texel's edge or of the bias: allow 0.5%.
TEST_F(GpuTest, SsaoMatchesTheCpuEstimator) {
  Renderer renderer(*builtin_scene("default"));
  const int width = 128, height = 96;
  SsaoSettings other;
  other.samples = 7;
  other.radius = 1.2f;
  other.bias = 0.05f;
  other.range = 5.0f;
  for (SsaoSettings ssao : {SsaoSettings{}, other}) {
    ssao.blur = 0;
    Image gpu = render_ao(renderer, ssao, width, height);
    const GBufferData g = read_gbuffer(renderer.gbuffer());
    const CpuSsao cpu(g, renderer.camera_view(), renderer.camera_projection(width, height), ssao);
    int differing = 0, occluded = 0;
    double max_difference = 0.0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const double expected = cpu.ao(x, y);
        const double d = std::abs(gpu.pixel(x, height - 1 - y)[0] - expected);
        differing += d > 1e-4;
        occluded += expected < 0.99;
        max_difference = std::max(max_difference, d);
      }
    }
    std::printf(
        "%d samples, r %.1f: %d of %d pixels differ from the CPU estimator by > 1e-4 "
        "(max %.3f); %d pixels occluded\n",
        ssao.samples, ssao.radius, differing, width * height, max_difference, occluded);
    EXPECT_GT(occluded, 200);
    EXPECT_LT(differing, width * height / 200);
  }
}

}  // namespace
}  // namespace penumbra
