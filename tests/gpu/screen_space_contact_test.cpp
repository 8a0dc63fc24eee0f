// --contact-shadows: a thin slab lying on the ground, lit at a grazing
// angle. Its shadow on the ground is a strip a few slab-heights long; the
// shadow map's slope-scaled bias at that angle is larger than the depth
// between the slab and the ground there, so every technique lets light
// under it (the contact line is lit where the traced reference is dark).
// The march through the camera's depth buffer towards the light finds the
// slab's face and darkens the strip as the reference does, for spot, sun
// and point lights, without darkening what the reference lights.
#include <cmath>
#include <cstdio>
#include <string>

#include "gpu_fixture.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::point_light;
using testing::small_frame;
using testing::spot_light;
using testing::sun_light;
using testing::TestScene;

constexpr float kSlabHeight = 0.02f;
constexpr float kSlabDepth = 0.6f;  // along z: the light comes from -z
// The light rises 8 degrees above the ground at the slab: its shadow is
// kSlabHeight / tan(8 degrees), about 0.14, long (within the first half of
// the march's default length, before its fade).
constexpr float kElevation = 0.14f;  // tan(8 degrees)

// A thin slab on the ground, seen from its shadow's side; the light comes
// from -z, kElevation above the ground at the slab.
Scene slab_scene(LightType type) {
  const glm::vec3 source(0.0f, 5.0f * kElevation, -5.0f);
  const Light light = type == LightType::Spot ? spot_light(source, glm::vec3(0.0f), 25.0f, 20.0f)
                      : type == LightType::Directional ? sun_light(-source)
                                                       : point_light(source, 30.0f);
  return TestScene("slab")
      .ground(8.0f)
      .box({0.0f, 0.5f * kSlabHeight, 0.0f}, {1.2f, kSlabHeight, kSlabDepth})
      .camera({0.0f, 0.8f, 1.3f}, {0.0f, 0.0f, 0.35f}, 30.0f)
      .light(light);
}

struct StripErrors {
  int strip = 0;         // ground pixels the reference shadows behind the slab
  double strip_lit = 0;  // the technique's mean there (the reference's is 0)
  int lit = 0;           // pixels the reference lights
  int darkened = 0;      // of them, darker than the reference by more than 0.5
};

StripErrors strip_errors(const Image& image, const Image& reference, const SurfacePoints& points) {
  StripErrors e;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (!points.covered[i] || reference.pixel(x, y)[3] < 0.5f) continue;
      const float ref = reference.pixel(x, y)[0];
      const float value = image.pixel(x, y)[0];
      const glm::vec3 p = points.position[i];
      const bool behind = p.z > 0.5f * kSlabDepth && std::abs(p.x) < 0.5f && p.y < 1e-3f;
      if (behind && ref < 0.01f) {
        ++e.strip;
        e.strip_lit += value;
      }
      if (ref > 0.99f) {
        ++e.lit;
        e.darkened += ref - value > 0.5f;
      }
    }
  }
  if (e.strip > 0) e.strip_lit /= e.strip;
  return e;
}

class ScreenSpaceContactTest : public GpuTest, public ::testing::WithParamInterface<LightType> {};

TEST_P(ScreenSpaceContactTest, DarkenTheContactLineTheMapLetsLightUnder) {
  Renderer renderer(slab_scene(GetParam()));
  const RenderSettings rs = small_frame(192, 108);
  ShadowSettings base;
  base.map_size = 256;
  base.light_size = 0.0f;  // a point source: the reference's shadow is binary
  base.sun_angle = 0.0f;
  base.cascades = 1;  // the sun's one map spans the view, as a spot light's does
  renderer.render(rs, base);
  const TracedReference reference = traced_reference(renderer, rs, base, 1, "");
  const SurfacePoints points = renderer.read_surfaces();
  for (const Technique technique : {Technique::Hard, Technique::Pcss, Technique::Vsm}) {
    for (const bool contact : {false, true}) {
      ShadowSettings shadow = base;
      shadow.technique = technique;
      shadow.contact_shadows = contact;
      renderer.render(rs, shadow);
      const StripErrors e = strip_errors(renderer.read_view(), reference.image, points);
      const std::string name = std::string(enum_name<Technique>(kTechniqueNames, technique)) +
                               (contact ? " --contact-shadows" : "");
      std::printf("%-30s strip of %d px: mean %.3f (reference 0); %d of %d lit px darkened\n",
                  name.c_str(), e.strip, e.strip_lit, e.darkened, e.lit);
      EXPECT_GT(e.strip, 150) << name;
      if (contact) {
        EXPECT_LT(e.strip_lit, 0.25) << name;
        EXPECT_LT(e.darkened, e.lit / 500) << name;
      } else {
        EXPECT_GT(e.strip_lit, 0.3) << name << ": the map no longer lets light under the slab";
      }
    }
  }
}

// What the march may not claim: occluders the depth buffer does not prove.
class ContactMarchTest : public GpuTest {};

struct Region {
  int pixels = 0;
  double reference = 0;  // the traced reference's mean over them
  double without = 0;    // the technique's mean without contact shadows
  double with = 0;       // and with them
};

// The means over the pixels `inside` picks among those the reference
// judges, of the reference and of `technique` without and with the march.
template <typename Inside>
Region region_means(Renderer& renderer, const RenderSettings& rs, const ShadowSettings& base,
                    int samples, Technique technique, Inside inside) {
  renderer.render(rs, base);
  const TracedReference reference = traced_reference(renderer, rs, base, samples, "");
  const SurfacePoints points = renderer.read_surfaces();
  Image shadow[2];
  for (const bool contact : {false, true}) {
    ShadowSettings s = base;
    s.technique = technique;
    s.contact_shadows = contact;
    renderer.render(rs, s);
    shadow[contact] = renderer.read_view();
  }
  Region r;
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * rs.width + x;
      if (!points.covered[i] || reference.image.pixel(x, y)[3] < 0.5f) continue;
      if (!inside(points.position[i], points.normal[i])) continue;
      ++r.pixels;
      r.reference += reference.image.pixel(x, y)[0];
      r.without += shadow[0].pixel(x, y)[0];
      r.with += shadow[1].pixel(x, y)[0];
    }
  }
  if (r.pixels > 0) {
    r.reference /= r.pixels;
    r.without /= r.pixels;
    r.with /= r.pixels;
  }
  std::printf("%d px: reference %.3f, without contact shadows %.3f, with %.3f\n", r.pixels,
              r.reference, r.without, r.with);
  return r;
}

// A rail 2 cm deep and 10 cm tall held 5 cm in front of a wall (the
// foliage scene's fence), under a sun 6 degrees off the wall's plane: the
// rays from the wall below the rail rise through the gap behind it and
// pass over its top; its shadow falls far lower. The camera, in front,
// sees the rail where those rays run, 5 cm behind it: within the 0.1
// thickness a march took for solid matter, the wall went dark there.
TEST_F(ContactMarchTest, RaysPassingBehindAThinBlockerStayLit) {
  const glm::vec3 to_sun = glm::normalize(glm::vec3(0.0f, 1.0f, 0.1f));
  Renderer renderer(TestScene("rail")
                        .ground(8.0f)
                        .box({0.0f, 1.0f, -0.1f}, {3.0f, 2.0f, 0.2f})  // the wall's face at z = 0
                        .box({0.0f, 0.55f, 0.06f}, {1.0f, 0.1f, 0.02f})
                        .camera({0.3f, 0.8f, 2.5f}, {0.0f, 0.45f, 0.0f}, 30.0f)
                        .light(sun_light(-to_sun)));
  ShadowSettings base;
  base.map_size = 512;
  base.sun_angle = 0.0f;
  base.cascades = 1;
  const Region r = region_means(renderer, small_frame(192, 108), base, 1, Technique::Pcss,
                                [](const glm::vec3& p, const glm::vec3& n) {
                                  return n.z > 0.99f && std::abs(p.z) < 1e-3f &&
                                         std::abs(p.x) < 0.4f && p.y > 0.25f && p.y < 0.48f;
                                });
  ASSERT_GT(r.pixels, 200);
  ASSERT_GT(r.reference, 0.99);
  ASSERT_GT(r.without, 0.95) << "the technique no longer lights the wall under the rail";
  EXPECT_GT(r.with, r.without - 0.02) << "the march darkens rays passing behind the rail";
}

// A box's front face under a sun 10 degrees wide whose centre lies 3
// degrees below the face's horizon: the disc's upper part, above it,
// lights the face, and nothing occludes that part (the reference's ratio
// is 1). Marched towards the centre, each step went into the box behind
// the face itself, which hid the whole source: the default scene's box
// went black under its 8.45-degree sun.
TEST_F(ContactMarchTest, MarchesTowardsThePartOfTheSourceAboveTheHorizon) {
  const float below = glm::radians(3.0f);
  const glm::vec3 to_sun(0.0f, std::cos(below), -std::sin(below));
  Renderer renderer(TestScene("face")
                        .ground(8.0f)
                        .box({0.0f, 0.5f, 0.0f}, glm::vec3(1.0f))
                        .camera({0.6f, 1.2f, 3.0f}, {0.0f, 0.5f, 0.5f}, 30.0f)
                        .light(sun_light(-to_sun)));
  ShadowSettings base;
  base.map_size = 512;
  base.sun_angle = 10.0f;
  base.cascades = 1;
  const Region r =
      region_means(renderer, small_frame(192, 108), base, 16, Technique::Backprojection,
                   [](const glm::vec3& p, const glm::vec3& n) {
                     return n.z > 0.99f && std::abs(p.z - 0.5f) < 1e-3f;
                   });
  ASSERT_GT(r.pixels, 500);
  ASSERT_GT(r.reference, 0.99);
  ASSERT_GT(r.without, 0.95) << "the technique no longer lights the face";
  EXPECT_GT(r.with, r.without - 0.02) << "the march darkens the face";
}

INSTANTIATE_TEST_SUITE_P(LightTypes, ScreenSpaceContactTest,
                         ::testing::Values(LightType::Spot, LightType::Directional,
                                           LightType::Point),
                         testing::light_type_name);

}  // namespace
}  // namespace penumbra
