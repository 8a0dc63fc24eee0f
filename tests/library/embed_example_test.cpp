// examples/embed, built against the installed package alone (find_package
// (penumbra), penumbra::shadows) and run headless by the test
// Install.EmbedExampleBuildsAgainstTheInstalledPackage
// (tests/library/embed_example.sh): its shadow images have
// the box's shadow where this test works it out from the example's scene
// (examples/embed/scene.hpp): a ground point is in shadow when the segment
// from it to the light crosses the box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <string>

#include "embed/scene.hpp"
#include "io/image.hpp"

namespace {

const std::string kWork = PENUMBRA_TEST_OUTPUT "/embed_example";
constexpr int kWidth = 320, kHeight = 180;

// Whether the segment a -> b crosses the box (slab test), ends excluded.
bool crosses_box(glm::vec3 a, glm::vec3 b) {
  const glm::vec3 lo = embed::kBoxCenter - embed::kBoxHalfSize;
  const glm::vec3 hi = embed::kBoxCenter + embed::kBoxHalfSize;
  const glm::vec3 d = b - a;
  float t0 = 1e-4f, t1 = 1.0f - 1e-4f;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-9f) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    float ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

enum class Expect { Lit, Shadowed, Unsure };

// The light as the test sees it: the far end of the shadow ray from a
// ground point, and whether the point is inside the light's reach.
struct TestLight {
  std::function<glm::vec3(glm::vec3)> source;
  std::function<bool(glm::vec3)> reaches;
};

TestLight spot_light() {
  const glm::vec3 axis = glm::normalize(embed::kSpotTarget - embed::kSpotPosition);
  return {[](glm::vec3) { return embed::kSpotPosition; },
          [axis](glm::vec3 p) {
            const float cos_angle = glm::dot(glm::normalize(p - embed::kSpotPosition), axis);
            return cos_angle > std::cos(glm::radians(embed::kSpotConeDegrees - 5.0f));
          }};
}

TestLight sun_light() {
  const glm::vec3 to_sun = -glm::normalize(embed::kSunDirection);
  return {[to_sun](glm::vec3 p) { return p + 100.0f * to_sun; }, [](glm::vec3) { return true; }};
}

// Lit or shadowed at ground point p and alike 0.25 around it (away from the
// penumbra's filtering), and seen by the camera; Unsure otherwise.
Expect expected_at(glm::vec3 p, const TestLight& light) {
  if (crosses_box(embed::kCameraPosition, p) || !light.reaches(p)) return Expect::Unsure;
  std::optional<bool> shadowed;
  for (float dx : {-0.25f, 0.0f, 0.25f}) {
    for (float dz : {-0.25f, 0.0f, 0.25f}) {
      const glm::vec3 q = p + glm::vec3(dx, 0.0f, dz);
      const bool s = crosses_box(q, light.source(q));
      if (shadowed && *shadowed != s) return Expect::Unsure;
      shadowed = s;
    }
  }
  return *shadowed ? Expect::Shadowed : Expect::Lit;
}

struct Tally {
  int shadowed = 0, lit = 0;
  int wrong_shadowed = 0, wrong_lit = 0;  // points that read lit, shadowed
  int partial = 0;  // seen ground points the light reaches that read neither 0 nor 1
};

// Compares the shadow factor image (1 = lit) with the expectation at ground
// points every 0.125 units, projected with the example's camera.
Tally check(const penumbra::Image& image, const TestLight& light) {
  const glm::mat4 view_projection =
      glm::perspective(glm::radians(embed::kCameraFovDegrees), static_cast<float>(kWidth) / kHeight,
                       embed::kCameraNear, embed::kCameraFar) *
      glm::lookAt(embed::kCameraPosition, embed::kCameraTarget, glm::vec3(0.0f, 1.0f, 0.0f));
  Tally tally;
  for (float x = -6.0f; x <= 6.0f; x += 0.125f) {
    for (float z = -6.0f; z <= 6.0f; z += 0.125f) {
      const glm::vec3 p(x, 0.0f, z);
      if (crosses_box(embed::kCameraPosition, p) || !light.reaches(p)) continue;
      const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
      const glm::vec2 ndc = glm::vec2(clip) / clip.w;
      const int px = static_cast<int>((ndc.x * 0.5f + 0.5f) * kWidth);
      const int py = static_cast<int>((0.5f - ndc.y * 0.5f) * kHeight);
      if (px < 1 || py < 1 || px >= kWidth - 1 || py >= kHeight - 1) continue;
      const float lit = image.pixel(px, py)[0];
      if (lit > 0.1f && lit < 0.9f) ++tally.partial;
      const Expect expect = expected_at(p, light);
      if (expect == Expect::Unsure) continue;
      if (expect == Expect::Shadowed) {
        ++tally.shadowed;
        if (lit > 0.25f) ++tally.wrong_shadowed;
      } else {
        ++tally.lit;
        if (lit < 0.75f) ++tally.wrong_lit;
      }
    }
  }
  return tally;
}

// images/<image>.png has the shadow of `light` where the test computes
// it: at least 20 shadowed and 100 lit points, at most 5 % of the shadowed
// ones read lit and 2 % of the lit ones shadowed.
void expect_shadow_where_computed(const std::string& image, const TestLight& light) {
  SCOPED_TRACE(image);
  const Tally t = check(penumbra::read_png(kWork + "/images/" + image + ".png"), light);
  EXPECT_GE(t.shadowed, 20);
  EXPECT_GE(t.lit, 100);
  EXPECT_LE(t.wrong_shadowed, t.shadowed / 20) << "of " << t.shadowed;
  EXPECT_LE(t.wrong_lit, t.lit / 50) << "of " << t.lit;
}

TEST(EmbedExample, SpotShadowWhereComputedForEveryTechnique) {
  for (const char* technique :
       {"hard", "pcf", "pcss", "backprojection", "vsm", "esm", "evsm2", "evsm4", "msm", "msm16"}) {
    expect_shadow_where_computed(std::string("spot-") + technique, spot_light());
  }
}

// The moment techniques filtered through summed-area tables (--filter
// sat): msm's moments quantized for the table, as the block says; and
// with --soft, the filter sized by the penumbra.
TEST(EmbedExample, SummedAreaTableShadowWhereComputed) {
  for (const char* image : {"sat-vsm", "sat-msm", "sat-msm16", "soft-vsm", "soft-msm"}) {
    expect_shadow_where_computed(std::string("spot-") + image, spot_light());
  }
}

TEST(EmbedExample, SunCascadeShadowWhereComputed) {
  for (const char* technique : {"pcf", "pcss", "vsm"}) {
    expect_shadow_where_computed(std::string("sun-") + technique, sun_light());
  }
}

// The soft-shadow techniques see the spot light's source (its Light::
// light_size): the box's shadow on the ground has a penumbra, points that
// are neither lit nor shadowed; hard shadows have none.
TEST(EmbedExample, SoftTechniquesDrawAPenumbra) {
  const auto partial = [](const char* technique) {
    return check(penumbra::read_png(kWork + "/images/spot-" + technique + ".png"), spot_light())
        .partial;
  };
  const int hard = partial("hard");
  EXPECT_LE(hard, 2);
  for (const char* technique : {"pcss", "backprojection", "soft-msm"}) {
    SCOPED_TRACE(technique);
    EXPECT_GE(partial(technique), 20) << "hard: " << hard;
  }
}

// The lit image: ground in either light's shadow is darker than ground
// that both light (the engine's own lighting multiplies penumbra_shadow()
// into each light's contribution).
TEST(EmbedExample, LitImageDarkerInEachLightsShadow) {
  const penumbra::Image image = penumbra::read_png(kWork + "/images/final.png");
  const TestLight spot = spot_light(), sun = sun_light();
  const glm::mat4 view_projection =
      glm::perspective(glm::radians(embed::kCameraFovDegrees), static_cast<float>(kWidth) / kHeight,
                       embed::kCameraNear, embed::kCameraFar) *
      glm::lookAt(embed::kCameraPosition, embed::kCameraTarget, glm::vec3(0.0f, 1.0f, 0.0f));
  // Mean green of the ground points in [-3, 3]^2 with these expectations.
  auto mean = [&](Expect from_spot, Expect from_sun) {
    double sum = 0.0;
    int count = 0;
    for (float x = -3.0f; x <= 3.0f; x += 0.125f) {
      for (float z = -3.0f; z <= 3.0f; z += 0.125f) {
        const glm::vec3 p(x, 0.0f, z);
        if (expected_at(p, spot) != from_spot || expected_at(p, sun) != from_sun) continue;
        const glm::vec4 clip = view_projection * glm::vec4(p, 1.0f);
        const int px = static_cast<int>((clip.x / clip.w * 0.5f + 0.5f) * kWidth);
        const int py = static_cast<int>((0.5f - clip.y / clip.w * 0.5f) * kHeight);
        sum += image.pixel(px, py)[1];
        ++count;
      }
    }
    EXPECT_GT(count, 3);
    return count > 0 ? sum / count : 0.0;
  };
  const double lit = mean(Expect::Lit, Expect::Lit);
  const double spot_shadow = mean(Expect::Shadowed, Expect::Lit);
  const double sun_shadow = mean(Expect::Lit, Expect::Shadowed);
  EXPECT_LT(spot_shadow, lit - 0.05) << "lit " << lit;
  EXPECT_LT(sun_shadow, lit - 0.05) << "lit " << lit;
  EXPECT_GT(sun_shadow, 0.05) << "the spot light still lights the sun's shadow";
}

}  // namespace
