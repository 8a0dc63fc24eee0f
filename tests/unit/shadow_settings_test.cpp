// The shadow core's settings list shadow parameters only: ShadowMapSettings,
// what ShadowMaps takes, has none of the fields only penumbra's renderer
// reads (accumulation and its sub-frames, the front ends' source sizes for
// every light at once); each light carries its own source size, which
// --light-size and --sun-angle override for every light of their kind once
// set, and not before.
#include <gtest/gtest.h>

#include "penumbra/error.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {
namespace {

template <class T>
concept HasAccumulate = requires(T t) {
  t.accumulate;
};
template <class T>
concept HasSubframe = requires(T t) {
  t.subframe_cell;
};
template <class T>
concept HasLightSize = requires(T t) {
  t.light_size;
};

template <class T>
concept HasContactShadows = requires(T t) {
  t.contact_shadows;
};
template <class T>
concept HasPagePool = requires(T t) {
  t.page_pool_mib;
};

static_assert(!HasAccumulate<ShadowMapSettings> && !HasSubframe<ShadowMapSettings> &&
              !HasLightSize<ShadowMapSettings> && !HasContactShadows<ShadowMapSettings>);
// Virtual shadow maps are the shadow core's (ShadowMaps draws them too).
static_assert(HasPagePool<ShadowMapSettings>);
static_assert(HasAccumulate<ShadowSettings> && HasSubframe<ShadowSettings> &&
              HasLightSize<ShadowSettings>);

TEST(ShadowMapSettings, TablesNameNoRendererParameter) {
  for (const auto& p : kShadowFloatParams) {
    EXPECT_NE(p.name, "light-size");
    EXPECT_NE(p.name, "sun-angle");
  }
  for (const auto& p : kShadowIntParams) EXPECT_NE(p.name, "accumulate");
}

TEST(SourceSizeOverride, SetsEveryLightOfItsKindOnceSet) {
  Light spot;
  spot.light_size = 1.5f;
  Light sun;
  sun.type = LightType::Directional;
  sun.sun_angle = 0.53f;
  ShadowSettings settings;
  EXPECT_FALSE(settings.light_size.is_set());
  // Unset, the override reads as the lights' default and changes no light.
  EXPECT_EQ(static_cast<float>(settings.light_size), Light{}.light_size);
  EXPECT_EQ(with_source_size(spot, settings).light_size, 1.5f);
  EXPECT_EQ(with_source_size(sun, settings).sun_angle, 0.53f);
  // Set, even to the default, it is every light's size.
  settings.light_size = Light{}.light_size;
  EXPECT_TRUE(settings.light_size.is_set());
  EXPECT_EQ(with_source_size(spot, settings).light_size, Light{}.light_size);
  EXPECT_EQ(with_source_size(sun, settings).sun_angle, 0.53f);
  settings.sun_angle = 4.0f;
  EXPECT_EQ(with_source_size(sun, settings).sun_angle, 4.0f);
  EXPECT_NE(settings, ShadowSettings{});
}

TEST(SourceSizeOverride, ValidateRefusesSizesOutOfRange) {
  Light light;
  EXPECT_NO_THROW(validate(light));
  light.light_size = -0.5f;
  EXPECT_THROW(validate(light), UsageError);
  light = Light{};
  light.sun_angle = 46.0f;
  EXPECT_THROW(validate(light), UsageError);
  ShadowSettings settings;
  settings.light_size = 101.0f;
  EXPECT_THROW(validate(settings), UsageError);
}

}  // namespace
}  // namespace penumbra
