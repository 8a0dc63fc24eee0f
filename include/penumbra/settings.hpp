#pragma once
// The shadow core's settings: ShadowMapSettings (technique, map size,
// biases, filter, cascades; every field documented with its default: what
// ShadowMaps takes), the technique and filter enums with their names, and
// the parameter tables that give each parameter its flag name, help text
// and range, so an engine's UI can offer them exactly as penumbra's own
// command line does. validate(const ShadowMapSettings&) throws UsageError
// naming the parameter out of range.
//
// The same tables are the one source of every front end's parameters
// (penumbra's CLI, viewer, scene files and report): each has its name,
// help, range and default here and nowhere else; the renderer's own
// settings (ShadowSettings' accumulation and source sizes, SSAO, the
// reference, the image) live here beside them for that reason.
#include <array>
#include <string_view>
#include <utility>

#include "penumbra/enum_names.hpp"
#include "penumbra/light.hpp"
#include "penumbra/shared/bindings.h"

// A macro's value as a string literal (help texts that quote shader constants).
#define PENUMBRA_QUOTED_TEXT(x) #x
#define PENUMBRA_QUOTED(x) PENUMBRA_QUOTED_TEXT(x)

namespace penumbra {

enum class Technique { None, Hard, Pcf, Pcss, Backprojection, Vsm, Esm, Msm, Msm16, Evsm2, Evsm4 };

inline constexpr std::array<std::pair<Technique, std::string_view>, 11> kTechniqueNames{{
    {Technique::None, "none"},
    {Technique::Hard, "hard"},
    {Technique::Pcf, "pcf"},
    {Technique::Pcss, "pcss"},
    {Technique::Backprojection, "backprojection"},
    {Technique::Vsm, "vsm"},
    {Technique::Esm, "esm"},
    {Technique::Msm, "msm"},
    {Technique::Msm16, "msm16"},
    {Technique::Evsm2, "evsm2"},
    {Technique::Evsm4, "evsm4"},
}};

// Techniques whose map is a filterable representation of depth (moments or
// an exponential) rather than depth itself.
constexpr bool is_filterable(Technique t) {
  return t == Technique::Vsm || t == Technique::Esm || t == Technique::Msm ||
         t == Technique::Msm16 || t == Technique::Evsm2 || t == Technique::Evsm4;
}

// Whether the technique's map can be summed in the 32-bit fixed-point
// summed-area table: not the exponential ones, whose values span dozens of
// orders of magnitude (validate() refuses them with --filter sat).
constexpr bool supports_sat(Technique t) {
  return is_filterable(t) && t != Technique::Esm && t != Technique::Evsm2 && t != Technique::Evsm4;
}

enum class Filter { Gaussian, Sat };

inline constexpr std::array<std::pair<Filter, std::string_view>, 2> kFilterNames{{
    {Filter::Gaussian, "gaussian"},
    {Filter::Sat, "sat"},
}};

// Whether --soft applies: the moment techniques (vsm, msm, msm16) filtered
// by the summed-area table, from which the penumbra-sized filter is read.
constexpr bool supports_soft_shadows(Technique t, Filter f) {
  return f == Filter::Sat && (t == Technique::Vsm || t == Technique::Msm || t == Technique::Msm16);
}

// Where a directional or spot light's shadow is stored: cascades (a fixed
// number of maps along the camera's view) and one map a spot, or virtual
// maps in 128^2 pages (a directional light's clipmap of 16,384^2 texels per
// level, a spot light's 16,384^2 map with mip levels), only the pages the
// camera's pixels need resident in a physical pool (docs/rendering.md,
// "Virtual shadow maps").
enum class ShadowMapKind { Cascades, Virtual };

inline constexpr std::array<std::pair<ShadowMapKind, std::string_view>, 2> kShadowMapKindNames{{
    {ShadowMapKind::Cascades, "cascades"},
    {ShadowMapKind::Virtual, "virtual"},
}};

// Whether a technique reads virtual shadow maps: the depth-map techniques,
// which read texels one by one through the page table. The moment
// techniques filter their maps as whole textures (a blur or a summed-area
// table across page borders), so they stay on cascades.
constexpr bool supports_virtual_maps(Technique t) {
  return t == Technique::None || t == Technique::Hard || t == Technique::Pcf ||
         t == Technique::Pcss || t == Technique::Backprojection;
}

enum class View {
  Final,
  Shadow,
  ShadowReference,
  ShadowMap,
  Moments,
  MomentsFiltered,
  Normals,
  Albedo,
  Ao,
  Cascades,
  Pages,
  TexelDensity
};

inline constexpr std::array<std::pair<View, std::string_view>, 12> kViewNames{{
    {View::Final, "final"},
    {View::Shadow, "shadow"},
    {View::ShadowReference, "shadow-reference"},
    {View::ShadowMap, "shadow-map"},
    {View::Moments, "moments"},
    {View::MomentsFiltered, "moments-filtered"},
    {View::Normals, "normals"},
    {View::Albedo, "albedo"},
    {View::Ao, "ao"},
    {View::Cascades, "cascades"},
    {View::Pages, "pages"},
    {View::TexelDensity, "texel-density"},
}};

// Names of on/off switches on the command line.
inline constexpr std::array<std::pair<bool, std::string_view>, 2> kOnOffNames{{
    {true, "on"},
    {false, "off"},
}};

// Views that show a light's map rather than the camera's image.
constexpr bool is_map_view(View v) {
  return v == View::ShadowMap || v == View::Moments || v == View::MomentsFiltered;
}

// What the shadow core (ShadowMaps, its passes and its lookup) reads: shadow
// parameters only. A light's source size is the light's own
// (Light::light_size, Light::sun_angle).
struct ShadowMapSettings {
  Technique technique = Technique::Hard;
  // Shadow-map width and height in texels.
  int map_size = 2048;
  // Constant depth bias, in shadow-map texels (the world size of a texel at
  // the receiver, converted to each shadow view's own depth range, so the
  // bias means the same at every scene scale).
  float constant_bias = 0.5f;
  // Slope-scaled bias: multiples of the receiver's depth change across one texel.
  float slope_bias = 1.5f;
  // Largest tan(angle to the light) the slope-scaled bias follows (backprojection:
  // at most BACKPROJECTION_BIAS_MAX_SLOPE) and the receiver's depth gradient takes.
  float max_slope = 10.0f;
  // Filtered techniques (vsm, esm, msm, msm16): extra slope-scaled bias per
  // texel of filter radius W, since a filter spreads a planar receiver's
  // own depth over +-W texels of its slope. Without it, MSM darkens sloped
  // lit surfaces under wide filters (measured on the default scene).
  float filter_slope_bias = 0.25f;
  // Normal offset: the lookup moves this many texels along the surface normal
  // (backprojection: none where the surface's slope from the light is under
  // max_slope, all of it at grazing and beyond; backprojection_normal_offset()).
  float normal_offset = 0.5f;

  // PCF: width of the square window in texels (0: the plain hard test),
  // sampled with the first pcf_samples points of the Poisson set (1: the
  // hardware's 2x2 bilinear compare).
  float pcf_width = 4.0f;
  int pcf_samples = 16;
  // PCSS (Fernando 2005): the most samples of the blocker search (each
  // gathers 2x2 texels) and of the PCF over the estimated penumbra (each a
  // 2x2 bilinear compare); fewer where the region is narrow (one per 4
  // texels searched, one per texel filtered).
  int pcss_blocker_samples = 32;
  int pcss_filter_samples = 64;
  // Backprojection (shaders/shadow/backprojection.glsl): patches per side
  // of the blockers' region at most. A region up to this many texels wide
  // is read texel by texel, a wider one from the depth hierarchy's level
  // whose cells it spans in at most this many, so the work per pixel is
  // bounded. A cell stands at the mean depth of its texels, and one that a
  // silhouette cuts is read texel by texel where the cells are 4 texels
  // wide (docs/rendering.md). 640x360, 2048^2 maps, 256 rays, the default
  // scene's spot at 1.5: RMSE 0.0049 at 16, 0.0038 at 32, 0.0028 at 64;
  // the lighting pass (bench, llvmpipe) 400, 602 and 1066 ms, PCSS's 79
  // ms; 96 and 128 buy no more (docs/rendering.md). Virtual shadow maps
  // read their region texel by texel at a level where it spans at most
  // VIRTUAL_BACKPROJECTION_WINDOW texels.
  int backprojection_cells = 64;
  // Moment soft shadows (vsm, msm, msm16 with --filter sat): the filter
  // width follows the estimated penumbra, at least the fixed --blur.
  bool soft = false;
  // msm/msm16 --soft: the blockers' depth from the mean and the occluded
  // fraction, as vsm estimates it, instead of Peters' quadrature.
  bool soft_two_moment_blockers = false;

  // Samples per shadow-map texel (1, 2, 4 or 8): the casters are drawn
  // into a multisampled depth target (seed 002: "render the scene from the
  // light's view to a multisampled depth buffer"). The filterable
  // techniques (vsm, esm, evsm2/4, msm, msm16) average every sample's
  // moments (or exponentials) in the resolve, so a texel a caster's edge
  // crosses holds the mean of what it covers, antialiased before the
  // filter; their depth maps (--soft's blocker search, the shadow-map
  // view) hold the nearest of each texel's samples. The techniques that
  // read depth (hard, pcf, pcss, backprojection) draw their maps with one
  // sample whatever this says (depth_samples()). 1: one sample at the
  // texel's centre.
  int shadow_msaa = 1;

  // Filtering of the vsm, esm, msm and msm16 maps.
  Filter filter = Filter::Gaussian;
  // Filter radius W in texels: a Gaussian of 2W+1 taps (s = W/2), or a
  // (2W+1)^2 box from the summed-area table. 0: no filtering.
  int blur = 2;
  // Gaussian filters of radius 1..kMaxFusedBlur: resolve and blur in one
  // compute pass (Peters et al., HPG 2017) instead of a resolve and two
  // blur passes. Same maps up to rounding; off measures the two-pass path.
  bool fused = true;
  // Mipmapped filtered maps (vsm, esm, evsm2/4, msm, msm16 with the
  // Gaussian filter or none): after the filter, a 2x2 box chain down to
  // 1x1, read with trilinear and anisotropic filtering over the pixel's
  // footprint on the receiver, so distant receivers average the map over
  // what the pixel covers instead of aliasing (MJP's EnableShadowMips).
  bool shadow_mips = false;
  // --shadow-mips: the largest ratio of a pixel's footprint's long side to
  // its short side that the lookup follows with anisotropic filtering
  // (clamped to the device's GL_MAX_TEXTURE_MAX_ANISOTROPY); 1: trilinear
  // only, the footprint's long side choosing the level. CPU rasterizers
  // (llvmpipe) filter trilinearly whatever this says (LightingPass).
  int shadow_anisotropy = 16;
  // ESM exponent c (Annen et al. 2008); the map stores exp(c (z - 1)).
  float esm_c = 60.0f;
  // EVSM exponents c+ and c- (Lauritzen & McCool 2008) of the warps
  // exp(c+ u) and -exp(-c- u), u = 2 z-bar - 1 (shaders/shadow/evsm.glsl):
  // Lauritzen's and MJP's defaults. evsm2 uses c+ only.
  float evsm_positive = 40.0f;
  float evsm_negative = 5.0f;
  // MSM moment bias alpha for 32-bit float moments of u = 2 z-bar - 1
  // (Peters & Klein 2015, Alg. 3), toward (0, 0.375, 0, 0.375) as in
  // Peters' JCGT 2017 code. Smaller is sharper (compare's error against the
  // filtered reference falls slightly down to 3e-7), but at filtered edges
  // near the far end of the depth range (tests/gpu/moment_shader_test.cpp)
  // float32 rounding then moves G by more than 0.05 (3e-7: up to 0.06 on
  // the GPU, 0.17 with the solve in double; 5e-7: 0.0498); 1e-6 keeps it
  // below 0.045.
  float msm_alpha = 1e-6f;
  // MSM moment bias alpha for 16-bit quantized moments, and for moments
  // summed in the fixed-point summed-area table, toward (0, 0.628, 0, 0.628).
  // 2e-5 measures better on the default scene but lets the float solve of
  // 16-bit far-end edges jump by up to 1.
  float msm16_alpha = 5e-5f;
  // VSM minimum variance, in squared shadow-map texels (converted per view
  // like the constant bias).
  float vsm_min_variance = 1.0f;
  // Light-bleeding reduction for vsm and msm: lit fractions below this
  // amount become 0 and the rest is rescaled. 0: off.
  float bleed_reduction = 0.0f;

  // Directional lights: shadow cascades along the camera's view (1-4).
  int cascades = 3;
  // Split scheme of the cascades: the blend lambda log + (1 - lambda)
  // uniform of Zhang et al.'s practical split scheme (2006).
  float cascade_lambda = 0.75f;
  // Fraction of each cascade, at its far end, over which it blends into the
  // next one.
  float cascade_blend = 0.1f;
  // Directional lights: fit each cascade to the geometry its camera slice
  // sees, plus its blockers' reach through the sun's disc (texels 1.4 to 2
  // times finer, a size that steps as the camera turns), instead of its
  // slice's bounding sphere, which does not turn with the camera.
  // cascades.hpp.
  bool tight_cascades = false;
  // Point lights: widen each cube face's frustum beyond 90 degrees by the
  // filter's reach plus a margin, in texels, so a filter near a face's edge
  // reads the scene from its own face (no seams between faces).
  bool guard_band = true;

  // Directional and spot lights: cascades and spot maps, or virtual shadow
  // maps (a directional light's clipmap of 16,384^2-texel levels, a spot's
  // 16,384^2 map with mip levels, in 128^2 pages, only the pages the
  // camera's pixels read resident in a page pool). Virtual maps mark their
  // pages from the camera's depth buffer (CameraDepthBuffer). ShadowMaps
  // draws the first directional light's virtual maps, for hard and pcf;
  // penumbra's renderer every directional and spot light's, for pcss and
  // backprojection too.
  ShadowMapKind shadow_maps = ShadowMapKind::Cascades;
  // Virtual shadow maps: the physical page pool's size in MiB of 32-bit
  // depth (64 KiB a page). 48: the memory of 3 cascades of 2048^2.
  int page_pool_mib = 48;

  bool operator==(const ShadowMapSettings&) const = default;
};

// --light-size or --sun-angle: one source size for every light of a kind,
// once a front end sets it (the command line when the flag is given, the
// viewer, the report's sweeps); until then each light keeps its own
// (Light::light_size, Light::sun_angle: a scene file's, or their default,
// which this reads as while unset).
class SourceSizeOverride {
 public:
  explicit constexpr SourceSizeOverride(float light_default) : size_(light_default) {}
  constexpr SourceSizeOverride& operator=(float size) {
    size_ = size;
    set_ = true;
    return *this;
  }
  // The size given, or, unset, the lights' default.
  constexpr operator float() const { return size_; }
  [[nodiscard]] constexpr bool is_set() const { return set_; }
  // A light's size under the override: the size given, or its own.
  [[nodiscard]] constexpr float of(float own) const { return set_ ? size_ : own; }
  constexpr bool operator==(const SourceSizeOverride&) const = default;

 private:
  float size_;
  bool set_ = false;
};

// What penumbra's renderer reads: the shadow core's settings, and what
// only the renderer does with them (accumulated soft shadows, source
// sizes set for every light at once).
struct ShadowSettings : ShadowMapSettings {
  // Screen-space contact shadows, with every technique, in penumbra's
  // renderer (ShadowMaps' lookup has no camera depth buffer to march): from
  // each lit pixel, contact_shadow_steps dithered steps through the
  // camera's depth buffer towards the part of the light's source above the
  // horizon, over contact_shadow_length world units; a step behind a
  // surface seen in front of it by less than contact_shadow_thickness is
  // occluded where the ray went into an opaque surface the buffer holds.
  // They catch what the map's bias and resolution let light under
  // (creases, the foot of a model); the light's factor is the smaller of
  // the technique's and theirs (shaders/render/contact_shadow.glsl).
  bool contact_shadows = false;
  float contact_shadow_length = 0.3f;
  float contact_shadow_thickness = 0.1f;
  int contact_shadow_steps = 16;

  // Spot lights' square width and point lights' sphere diameter in world
  // units (--light-size), and directional lights' angular diameter in
  // degrees (--sun-angle), for every light of the kind once set.
  SourceSizeOverride light_size{Light{}.light_size};
  SourceSizeOverride sun_angle{Light{}.sun_angle};

  // Accumulated soft shadows (render, compare, view): this many sub-frames, each
  // with the shadow maps rendered from another point of the light's source
  // (its light_size or sun_angle), averaged. 1: one frame from the light's centre.
  int accumulate = 1;
  // Set for each sub-frame by render_subframe, not by the user: the
  // sub-frame's index; its point of a spot light's square, in [0, 1]^2;
  // the cell of the square holding it, within which the hard test dithers
  // each pixel's points (shaders/shadow/accumulate.glsl): its lower corner
  // and size in [0, 1]^2, and its column of `columns` and row of the
  // `rows` its column holds (the cells have equal area, one per
  // sub-frame); and the source's outward normal at the point (spot, point
  // lights), which weights the shadow view.
  int subframe = 0;
  float subframe_u = 0.5f;
  float subframe_v = 0.5f;
  std::array<float, 4> subframe_cell{0.0f, 0.0f, 1.0f, 1.0f};  // x, y, width, height
  std::array<int, 4> subframe_cell_index{0, 1, 0, 1};          // column, columns, row, rows
  std::array<float, 3> subframe_normal{0.0f, 0.0f, 0.0f};

  bool operator==(const ShadowSettings&) const = default;
};

// The light with the settings' source sizes (light_size, sun_angle) where
// they are set.
constexpr Light with_source_size(Light light, const ShadowSettings& settings) {
  light.light_size = settings.light_size.of(light.light_size);
  light.sun_angle = settings.sun_angle.of(light.sun_angle);
  return light;
}

// Screen-space ambient obscurance (seed 003, Task 6) over the G-buffer: k
// points in the hemisphere of radius r around the normal, each counted as
// unoccluded when the depth buffer does not hide it (within the depth bias),
// or when it lies more than range * r behind the surface that hides it.
struct SsaoSettings {
  bool enabled = true;
  // Samples per pixel, k.
  int samples = 16;
  // Hemisphere radius r in world units: the reach of the obscurance. About
  // the size of the default scene's objects, so the ground darkens under
  // the sphere floating 0.9 above it as well as at the feet of the others.
  float radius = 1.0f;
  // Depth bias in world units: a sample counts as hidden only when it lies
  // more than this behind the surface seen in its direction. That surface's
  // depth is taken on its tangent plane (exact for planes), so the bias only
  // absorbs what a plane does not describe: the facets of tessellated curved
  // surfaces, whose interpolated normals lean over them.
  float bias = 0.02f;
  // Range check, in multiples of r: a sample hidden by a surface more than
  // range * r in front of it counts as unoccluded (seed 003 uses 5). That
  // surface is then more than (range - 1) r from the shaded point, so 2 is
  // the smallest range that never discards an occluder seen within r of it;
  // larger ranges let objects floating in front of a surface darken it in a
  // halo around their silhouettes (measured: a sphere 1.1 above the ground
  // seen from 35 degrees darkens the ground to 0.51 at range 5 with
  // r = 0.5, not at all at 2; the contact darkening at a box's foot is the
  // same at both).
  float range = 2.0f;
  // Radius in AO texels of the depth- and normal-aware blur; 0: none. At 6
  // no trace of the per-pixel rotation's pattern is left with 16 samples
  // (at 4 its diagonal streaks remain on the ground of the default scene).
  int blur = 6;
  // Computes the AO at half the width and height, then upsamples it with
  // depth and normal awareness.
  bool half_resolution = false;

  bool operator==(const SsaoSettings&) const = default;
};

// The ray-traced reference (src/reference/): how it samples. The light's
// size is the techniques' own: Light::light_size (spot, point) or
// sun_angle (directional), under ShadowSettings' overrides.
struct ReferenceSettings {
  // Shadow rays per pixel towards an area light (a source size > 0), spread
  // over the light by correlated multi-jittered sampling; a point light
  // takes one ray.
  int samples = 256;
};

struct RenderSettings {
  int width = 1280;
  int height = 720;
  View view = View::Final;
  // Which light the shadow and shadow-map views show.
  int light_index = 0;
};

// The sections of every command's --help, in the order they are shown.
// A parameter's group is part of its table entry below; one without a
// group (Unset) is shown in its table's section (see add_params in
// src/app/options.cpp), and tests/unit/cli_help_test.cpp lists it.
enum class OptionGroup {
  Unset,
  Output,
  SceneAndCamera,
  Lights,
  Technique,
  Filter,
  SoftShadows,
  Bias,
  Ssao,
  Reference,
  Measurement,
  Other,
};

inline constexpr std::array<std::pair<OptionGroup, std::string_view>, 11> kOptionGroupNames{{
    {OptionGroup::Output, "Output"},
    {OptionGroup::SceneAndCamera, "Scene and camera"},
    {OptionGroup::Lights, "Lights"},
    {OptionGroup::Technique, "Technique"},
    {OptionGroup::Filter, "Filter"},
    {OptionGroup::SoftShadows, "Soft shadows"},
    {OptionGroup::Bias, "Bias"},
    {OptionGroup::Ssao, "SSAO"},
    {OptionGroup::Reference, "Reference"},
    {OptionGroup::Measurement, "Measurement"},
    {OptionGroup::Other, "Other"},
}};

// A numeric parameter: flag name (without "--"), help, range, where it
// lives, and its --help section. The default is the struct member's
// initializer.
template <class Settings, class T>
struct NumericParam {
  std::string_view name;
  std::string_view help;
  T min;
  T max;
  T Settings::*field;
  OptionGroup group = OptionGroup::Unset;
};

// An on/off parameter given as "--name" or "--no-name": flag name (without
// "--"), help, where it lives, and its --help section.
template <class Settings>
struct FlagParam {
  std::string_view name;
  std::string_view help;
  bool Settings::*field;
  OptionGroup group = OptionGroup::Unset;
};

inline constexpr int kMaxMapSize =
    32768;  // the largest any GPU offers; each GPU's own limit is checked too
inline constexpr int kMaxImageSize = 16384;

// The ESM map stores exp(c (z - 1)) in 32-bit float: in (0, 1], so it
// cannot overflow; c <= 87 keeps exp(-c) above the smallest normal float.
inline constexpr float kEsmMaxC = 87.0f;
// EVSM stores exp(c u)^2 for u in [-1, 1] in 32-bit float: exp(2 c) stays
// below the largest float (exp(88.7)) with room for a filter's sums up to
// c = 44; 42 as Lauritzen's and MJP's code clamp it.
inline constexpr float kEvsmMaxExponent = 42.0f;
inline constexpr int kMaxBlur = MAX_SOFT_RADIUS;
// Widest Gaussian the fused resolve + filter pass takes: its tile's apron
// then still fits the 32 KiB of shared memory every GL 4.5 device has.
inline constexpr int kMaxFusedBlur = 16;
inline constexpr int kMaxShadowSamples = 64;  // the size of the Poisson set
inline constexpr int kMaxContactShadowSteps = 64;
// Backprojection's patches per side of its region at most. llvmpipe ends
// every loop of a shader invocation once they have run 65535 iterations
// in all (for the eight pixels it shades together), and a lookup cut
// short reads lit: at 256 the default scene's point light 3 wide lost
// 1732 of 230 400 pixels (640x360), at 128 none, nor the foliage's lights.
inline constexpr int kMaxBackprojectionCells = 128;
// --shadow-msaa takes the sample counts every GL 4.5 device can offer for a
// depth texture, powers of two (GL_MAX_DEPTH_TEXTURE_SAMPLES is at least 1;
// each device's own limit is checked where the maps are made).
inline constexpr int kMaxShadowMsaa = 8;

// --max-slope's help, quoting backprojection's own cap (shared/bindings.h).
inline constexpr std::string_view kMaxSlopeHelp =
    "largest slope tan(theta) the slope-scaled bias follows (backprojection: at "
    "most " PENUMBRA_QUOTED(
        BACKPROJECTION_BIAS_MAX_SLOPE) ") and the receiver's depth gradient takes";

inline constexpr std::array<NumericParam<ShadowMapSettings, float>, 15> kShadowFloatParams{{
    {"constant-bias",
     "constant depth bias, in shadow-map texels (a texel's world size at the receiver)", 0.0f,
     64.0f, &ShadowMapSettings::constant_bias, OptionGroup::Bias},
    {"slope-bias", "slope-scaled depth bias, in texels of the receiver's depth slope", 0.0f, 64.0f,
     &ShadowMapSettings::slope_bias, OptionGroup::Bias},
    {"max-slope", kMaxSlopeHelp, 0.0f, 1000.0f, &ShadowMapSettings::max_slope, OptionGroup::Bias},
    {"filter-slope-bias", "filtered techniques: extra slope-scaled bias per texel of filter radius",
     0.0f, 4.0f, &ShadowMapSettings::filter_slope_bias, OptionGroup::Bias},
    {"normal-offset",
     "normal-offset distance, in shadow-map texels (backprojection: none on a surface whose "
     "slope from the light is under --max-slope, all of it at grazing and beyond)",
     0.0f, 64.0f, &ShadowMapSettings::normal_offset, OptionGroup::Bias},
    {"pcf-width", "PCF window width in texels (0: the plain hard test)", 0.0f, MAX_PCF_WIDTH,
     &ShadowMapSettings::pcf_width, OptionGroup::Technique},
    {"esm-c", "ESM exponent c, per unit of the shadow view's relative depth z-bar", 1.0f, kEsmMaxC,
     &ShadowMapSettings::esm_c, OptionGroup::Technique},
    {"evsm-positive", "EVSM positive exponent c+ of exp(c+ (2 z-bar - 1)) (evsm2, evsm4)", 1.0f,
     kEvsmMaxExponent, &ShadowMapSettings::evsm_positive, OptionGroup::Technique},
    {"evsm-negative", "EVSM negative exponent c- of -exp(-c- (2 z-bar - 1)) (evsm4)", 1.0f,
     kEvsmMaxExponent, &ShadowMapSettings::evsm_negative, OptionGroup::Technique},
    {"msm-alpha",
     "MSM moment bias alpha for msm's 32-bit float moments of 2 z-bar - 1, toward (0, 0.375, 0, "
     "0.375); below about 5e-7 float rounding shows near the far end of the depth range",
     1e-8f, 0.5f, &ShadowMapSettings::msm_alpha, OptionGroup::Technique},
    {"msm16-alpha",
     "MSM moment bias alpha for msm16's 16-bit moments and for moments summed in the "
     "summed-area table (msm and msm16 with --filter sat), toward (0, 0.628, 0, 0.628)",
     1e-8f, 0.5f, &ShadowMapSettings::msm16_alpha, OptionGroup::Technique},
    {"vsm-min-variance",
     "VSM minimum variance, in squared shadow-map texels (EVSM: scaled by its warp's slope)", 0.0f,
     4096.0f, &ShadowMapSettings::vsm_min_variance, OptionGroup::Technique},
    {"bleed-reduction", "light-bleeding reduction for vsm, msm and evsm (0: off)", 0.0f, 0.99f,
     &ShadowMapSettings::bleed_reduction, OptionGroup::Technique},
    {"cascade-lambda",
     "directional lights: cascade split scheme, lambda * logarithmic + (1 - lambda) * uniform "
     "(Zhang et al. 2006)",
     0.0f, 1.0f, &ShadowMapSettings::cascade_lambda, OptionGroup::Lights},
    {"cascade-blend",
     "directional lights: fraction of each cascade, at its far end, blended into the next", 0.0f,
     0.5f, &ShadowMapSettings::cascade_blend, OptionGroup::Lights},
}};

// The page pool's largest size: 2048 pages of 64 KiB, the layers every
// GL 4.5 device allows an array texture.
inline constexpr int kMaxPagePoolMib = 128;

inline constexpr std::array<NumericParam<ShadowMapSettings, int>, 10> kShadowIntParams{{
    {"shadow-map-size", "shadow-map width and height in texels", 16, kMaxMapSize,
     &ShadowMapSettings::map_size, OptionGroup::Technique},
    {"shadow-msaa",
     "samples per shadow-map texel of vsm, esm, evsm2, evsm4, msm and msm16, 1, 2, 4 or 8 (up "
     "to the GPU's limit): each sample's moments are averaged before the filter, so the maps' "
     "edges are antialiased (hard, pcf, pcss and backprojection draw one sample)",
     1, kMaxShadowMsaa, &ShadowMapSettings::shadow_msaa, OptionGroup::Technique},
    {"blur", "filter radius W in texels (Gaussian of 2W+1 taps, or (2W+1)^2 SAT box); 0: none", 0,
     kMaxBlur, &ShadowMapSettings::blur, OptionGroup::Filter},
    {"pcf-samples", "PCF samples from the Poisson set (1: hardware 2x2 compare)", 1,
     kMaxShadowSamples, &ShadowMapSettings::pcf_samples, OptionGroup::Technique},
    {"pcss-blocker-samples",
     "PCSS blocker-search samples at most, each gathering 2x2 texels (one per 4 texels of the "
     "search region)",
     1, kMaxShadowSamples, &ShadowMapSettings::pcss_blocker_samples, OptionGroup::Technique},
    {"pcss-filter-samples",
     "PCSS filter samples at most, each a 2x2 bilinear compare (one per texel of the penumbra)", 1,
     kMaxShadowSamples, &ShadowMapSettings::pcss_filter_samples, OptionGroup::Technique},
    {"backprojection-cells",
     "backprojection: patches per side of the blockers' region at most (a region this many "
     "texels wide or less is read texel by texel, a wider one from coarser cells of the depth "
     "hierarchy); more is closer to the reference and slower (--shadow-maps virtual reads 64)",
     16, kMaxBackprojectionCells, &ShadowMapSettings::backprojection_cells, OptionGroup::Technique},
    {"cascades", "directional lights: shadow cascades along the camera's view", 1, MAX_CASCADES,
     &ShadowMapSettings::cascades, OptionGroup::Lights},
    {"shadow-anisotropy",
     "--shadow-mips: most anisotropic filtering along the pixel's footprint (up to the device's "
     "limit; llvmpipe: 1); 1: trilinear only",
     1, 16, &ShadowMapSettings::shadow_anisotropy, OptionGroup::Filter},
    {"page-pool-mib",
     "--shadow-maps virtual: the physical page pool in MiB (64 KiB of 32-bit depth a 128^2 "
     "page; 48 is the memory of 3 cascades of 2048^2)",
     1, kMaxPagePoolMib, &ShadowMapSettings::page_pool_mib, OptionGroup::Lights},
}};

inline constexpr int kMaxAccumulate = 4096;

// render, compare and view take it (view refines while nothing changes), not
// bench or report, so it is a table of its own.
inline constexpr std::array<NumericParam<ShadowSettings, int>, 1> kAccumulateParams{{
    {"accumulate",
     "average this many sub-frames, each with the shadow maps rendered from another point of "
     "the light's source (--light-size, --sun-angle; stratified, the same points every run); "
     "1: off",
     1, kMaxAccumulate, &ShadowSettings::accumulate, OptionGroup::SoftShadows},
}};

// The renderer's own shadow parameters, which ShadowMaps does not take:
// screen-space contact shadows.
inline constexpr std::array<NumericParam<ShadowSettings, int>, 1> kRendererShadowIntParams{{
    {"contact-shadow-steps", "--contact-shadows: steps of each pixel's march towards the light", 1,
     kMaxContactShadowSteps, &ShadowSettings::contact_shadow_steps, OptionGroup::Technique},
}};

inline constexpr std::array<NumericParam<ShadowSettings, float>, 2> kRendererShadowFloatParams{{
    {"contact-shadow-length",
     "--contact-shadows: how far each pixel's march towards the light reaches, in world units",
     1e-4f, 1000.0f, &ShadowSettings::contact_shadow_length, OptionGroup::Technique},
    {"contact-shadow-thickness",
     "--contact-shadows: how far behind a surface seen in the depth buffer a step still counts "
     "as occluded by it, in world units",
     1e-4f, 1000.0f, &ShadowSettings::contact_shadow_thickness, OptionGroup::Technique},
}};

// A light's source size: its own (Light, scene files' "light_size" and
// "sun_angle"), or, given on the command line, every light's of its kind
// (ShadowSettings' overrides).
struct SourceSizeParam {
  std::string_view name;
  std::string_view help;
  float min;
  float max;
  float Light::*light_field;
  SourceSizeOverride ShadowSettings::*override_field;
  OptionGroup group = OptionGroup::Unset;
};

inline constexpr std::array<SourceSizeParam, 2> kSourceSizeParams{{
    {"light-size",
     "width of a spot light's source in world units (0: a point), for pcss, backprojection, "
     "--soft and the area-light reference (a square facing the light's direction); a point "
     "light's source is a sphere of this diameter. Sets every spot and point light's size; "
     "without it each light keeps its own (a scene file's \"light_size\")",
     0.0f, 100.0f, &Light::light_size, &ShadowSettings::light_size, OptionGroup::Lights},
    {"sun-angle",
     "angular diameter of a directional light's source in degrees (0: a point); the reference "
     "traces the disc of directions this wide. Sets every directional light's; without it each "
     "keeps its own (a scene file's \"sun_angle\")",
     0.0f, 45.0f, &Light::sun_angle, &ShadowSettings::sun_angle, OptionGroup::Lights},
}};

inline constexpr int kMaxSsaoSamples = 64;  // SSAO_MAX_SAMPLES in shaders/shared/bindings.h
inline constexpr int kMaxSsaoBlur = 16;

inline constexpr std::array<NumericParam<SsaoSettings, int>, 2> kSsaoIntParams{{
    {"ssao-samples", "SSAO samples per pixel", 1, kMaxSsaoSamples, &SsaoSettings::samples,
     OptionGroup::Ssao},
    {"ssao-blur", "radius in AO texels of the depth- and normal-aware SSAO blur; 0: none", 0,
     kMaxSsaoBlur, &SsaoSettings::blur, OptionGroup::Ssao},
}};

inline constexpr std::array<NumericParam<SsaoSettings, float>, 3> kSsaoFloatParams{{
    {"ssao-radius", "SSAO hemisphere radius in world units", 1e-4f, 1000.0f, &SsaoSettings::radius,
     OptionGroup::Ssao},
    {"ssao-bias", "SSAO depth bias in world units", 0.0f, 100.0f, &SsaoSettings::bias,
     OptionGroup::Ssao},
    {"ssao-range",
     "SSAO range check: occluders more than this many radii in front of a sample are ignored", 0.0f,
     1000.0f, &SsaoSettings::range, OptionGroup::Ssao},
}};

inline constexpr std::array<FlagParam<ShadowMapSettings>, 2> kShadowFlagParams{{
    {"soft",
     "vsm/msm/msm16 with --filter sat: filter width follows the estimated penumbra (blocker "
     "search from the moments), at least --blur",
     &ShadowMapSettings::soft, OptionGroup::SoftShadows},
    {"soft-two-moment-blockers",
     "msm/msm16 --soft: estimate the blockers' depth from the mean depth and the occluded "
     "fraction with the unoccluded texels at the receiver's depth (Yang et al. 2010, as vsm "
     "does) instead of the four-moment quadrature of Peters et al. 2016; closer at the "
     "bunny's foot, farther off in wide penumbrae",
     &ShadowMapSettings::soft_two_moment_blockers, OptionGroup::SoftShadows},
}};

inline constexpr std::array<NumericParam<RenderSettings, int>, 3> kRenderIntParams{{
    {"width", "image width in pixels", 1, kMaxImageSize, &RenderSettings::width,
     OptionGroup::Output},
    {"height", "image height in pixels", 1, kMaxImageSize, &RenderSettings::height,
     OptionGroup::Output},
    {"light-index", "which light the shadow and shadow-map views show (0 = first)", 0, 3,
     &RenderSettings::light_index, OptionGroup::Lights},
}};

inline constexpr int kMaxReferenceSamples = 65536;

inline constexpr std::array<NumericParam<ReferenceSettings, int>, 1> kReferenceIntParams{{
    {"reference-samples",
     "traced reference: shadow rays per pixel towards an area light (--light-size or "
     "--sun-angle > 0)",
     1, kMaxReferenceSamples, &ReferenceSettings::samples, OptionGroup::Reference},
}};

// An on/off parameter given as "--name" or "--no-name" like a FlagParam,
// and also, as it once was, as "--name on|off".
template <class Settings>
struct SwitchParam {
  std::string_view name;
  std::string_view help;
  bool Settings::*field;
  OptionGroup group = OptionGroup::Unset;
};

inline constexpr std::array<SwitchParam<ShadowMapSettings>, 4> kShadowSwitchParams{{
    {"tight-cascades",
     "directional lights: fit each cascade to the geometry its slice of the view sees, plus "
     "its blockers' reach through the sun's disc (texels 1.4 to 2 times finer; its size steps "
     "as the camera turns), instead of its slice's bounding sphere (which does not turn with "
     "the camera)",
     &ShadowMapSettings::tight_cascades, OptionGroup::Lights},
    {"guard-band",
     "point lights: widen each cube face's frustum by the filter's reach plus a margin, so "
     "filters near a face's edge read their own face (no seams)",
     &ShadowMapSettings::guard_band, OptionGroup::Lights},
    {"fused",
     "filterable techniques with --filter gaussian and --blur 1..16: resolve and blur in one "
     "compute pass; off (or a wider blur) runs the resolve, then the horizontal and vertical "
     "blur passes",
     &ShadowMapSettings::fused, OptionGroup::Filter},
    {"shadow-mips",
     "filterable techniques with --filter gaussian (or --blur 0): mip chain of the filtered map, "
     "read trilinearly and anisotropically over the pixel's footprint (distant receivers do not "
     "alias)",
     &ShadowMapSettings::shadow_mips, OptionGroup::Filter},
}};

// The renderer's contact shadows (kRendererShadowIntParams' neighbours).
inline constexpr std::array<SwitchParam<ShadowSettings>, 1> kRendererShadowSwitchParams{{
    {"contact-shadows",
     "with every technique: a short march through the camera's depth buffer from each lit pixel "
     "towards the light darkens what the shadow map misses (creases, the foot of a model)",
     &ShadowSettings::contact_shadows, OptionGroup::Technique},
}};

inline constexpr std::array<SwitchParam<SsaoSettings>, 2> kSsaoSwitchParams{{
    {"ssao", "screen-space ambient occlusion darkening the ambient light", &SsaoSettings::enabled,
     OptionGroup::Ssao},
    {"ssao-half-resolution",
     "compute the AO at half width and height, then upsample it with depth and normal awareness",
     &SsaoSettings::half_resolution, OptionGroup::Ssao},
}};

// Throws UsageError naming the first parameter outside its range.
void validate(const ShadowMapSettings& settings);
void validate(const ShadowSettings& settings);
// A light's source sizes (kSourceSizeParams).
void validate(const Light& light);
void validate(const RenderSettings& settings);
void validate(const SsaoSettings& settings);
void validate(const ReferenceSettings& settings);

}  // namespace penumbra
