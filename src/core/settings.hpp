#pragma once
// The settings every front end reads: the CLI, the viewer, scene files and
// the report. Each parameter has its name, help, range and default here and
// nowhere else (see the parameter tables below).
#include <array>
#include <string_view>
#include <utility>

#include "core/enum_names.hpp"

namespace penumbra {

enum class Technique { None, Hard };

inline constexpr std::array<std::pair<Technique, std::string_view>, 2> kTechniqueNames{{
    {Technique::None, "none"},
    {Technique::Hard, "hard"},
}};

enum class View { Final, Shadow, ShadowMap, Normals, Albedo };

inline constexpr std::array<std::pair<View, std::string_view>, 5> kViewNames{{
    {View::Final, "final"},
    {View::Shadow, "shadow"},
    {View::ShadowMap, "shadow-map"},
    {View::Normals, "normals"},
    {View::Albedo, "albedo"},
}};

struct ShadowSettings {
  Technique technique = Technique::Hard;
  // Shadow-map width and height in texels.
  int map_size = 2048;
  // Constant depth bias, in relative depth z-bar (fraction of the light's depth range).
  float constant_bias = 0.0005f;
  // Slope-scaled bias: multiples of the receiver's depth change across one texel.
  float slope_bias = 1.5f;
  // Largest tan(angle to the light) the slope-scaled bias follows.
  float max_slope = 10.0f;
  // Normal offset: the lookup moves this many texels along the surface normal.
  float normal_offset = 0.5f;
  // Width of the light source in world units (0: a point light, hard shadows).
  float light_size = 0.0f;
};

struct RenderSettings {
  int width = 1280;
  int height = 720;
  View view = View::Final;
  // Which light the shadow and shadow-map views show.
  int light_index = 0;
};

// A numeric parameter: flag name (without "--"), help, range, and where it
// lives. The default is the struct member's initializer.
template <class Settings, class T>
struct NumericParam {
  std::string_view name;
  std::string_view help;
  T min;
  T max;
  T Settings::*field;
};

inline constexpr int kMaxMapSize = 32768;  // the largest any GPU offers; each GPU's own limit is checked too
inline constexpr int kMaxImageSize = 16384;

inline constexpr std::array<NumericParam<ShadowSettings, float>, 5> kShadowFloatParams{{
    {"constant-bias", "constant depth bias, in relative light depth z-bar", 0.0f, 0.1f,
     &ShadowSettings::constant_bias},
    {"slope-bias", "slope-scaled depth bias, in texels of the receiver's depth slope", 0.0f, 64.0f,
     &ShadowSettings::slope_bias},
    {"max-slope", "largest slope tan(theta) the slope-scaled bias follows", 0.0f, 1000.0f,
     &ShadowSettings::max_slope},
    {"normal-offset", "normal-offset distance, in shadow-map texels", 0.0f, 64.0f,
     &ShadowSettings::normal_offset},
    {"light-size", "width of the light source in world units (0: point light)", 0.0f, 100.0f,
     &ShadowSettings::light_size},
}};

inline constexpr std::array<NumericParam<ShadowSettings, int>, 1> kShadowIntParams{{
    {"shadow-map-size", "shadow-map width and height in texels", 16, kMaxMapSize,
     &ShadowSettings::map_size},
}};

inline constexpr std::array<NumericParam<RenderSettings, int>, 3> kRenderIntParams{{
    {"width", "image width in pixels", 1, kMaxImageSize, &RenderSettings::width},
    {"height", "image height in pixels", 1, kMaxImageSize, &RenderSettings::height},
    {"light-index", "which light the shadow and shadow-map views show (0 = first)", 0, 3,
     &RenderSettings::light_index},
}};

// Throws UsageError naming the first parameter outside its range.
void validate(const ShadowSettings& settings);
void validate(const RenderSettings& settings);

}  // namespace penumbra
