#pragma once
// Measuring every pass of a frame over several frames: the numbers of
// `penumbra bench` and of the report's timing table.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/filter/texture_copy_pass.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/texel_traffic.hpp"
#include "render/renderer.hpp"

namespace penumbra {

inline constexpr auto kPassCount = static_cast<std::size_t>(gl::GpuPass::Count);

struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
};
Spread spread_of(std::vector<double> values);

// One pass's times over the measured frames, by both clocks.
struct Samples {
  std::vector<double> timer_ms, wall_ms;
};

// Bytes per texel of each pass a frame with these settings runs over a
// width x height shadow-map array, from the passes' own formats, tiles and
// aprons: the resolve, the filter's passes, the mip chain and the copy
// yardstick;
// nullopt for the passes that are not a pass over the map's texels (the
// shadow depth pass rasterizes; the camera's passes).
// `shared_bytes` is the device's GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, which
// sets the fused pass's tile (32 KiB: the least any GL 4.5 device has).
std::array<std::optional<TexelTraffic>, kPassCount> shadow_map_traffic(const ShadowSettings& shadow,
                                                                       int width, int height,
                                                                       int shared_bytes = 32768);

struct PassTimes {
  ShadowSettings shadow;
  std::array<Samples, kPassCount> passes;
  std::array<bool, kPassCount> ran{};
  Samples total;
  // The shadow-map array's texels (all layers) each pass went over, and
  // its bytes per texel.
  double texels = 0.0;
  std::array<std::optional<TexelTraffic>, kPassCount> traffic{};
};

// A pass's median time on one clock, and the bandwidth that is: the
// pass's bytes over its time (0 where either is unknown).
double median_ms(const Samples& samples, bool timer_clock);
// What the image of run.shadow.accumulate sub-frames (one frame each)
// costs as render, compare and report make it: the camera's G-buffer and
// ambient occlusion once (the renderer reuses them for the same camera),
// the shadow maps, filters and lighting once per sub-frame.
double converged_image_ms(const PassTimes& run, bool timer_clock);
double achieved_gb_per_second(const PassTimes& run, std::size_t pass, bool timer_clock);

// Renders warmup + frames frames, each followed by the bandwidth yardstick
// (a copy of light 0's map), with a serializing profiler, and keeps the
// times of the last `frames`. Throws RuntimeError on a GL error.
PassTimes measure_pass_times(Renderer& renderer, const RenderSettings& render,
                             const ShadowSettings& shadow, int frames, int warmup);

// What the cached shadow maps cost (Renderer::forget_shadow_maps()): the
// shadow passes (depth, resolve, filters, mips) of a frame that draws
// every view, of a static frame (nothing changed since the one before: no
// view drawn) and of a frame where scene shape `shape` moved (a small step
// along x, back and forth), `frames` of each, with a serializing profiler.
struct CachedShadowTimes {
  Samples full, still, moving;
  int views = 0;          // the views a full frame draws
  int still_views = 0;    // the most a static frame drew (0)
  int moving_views = 0;   // the most a moving frame drew
  std::size_t shape = 0;  // the shape moved
};
CachedShadowTimes measure_cached_shadow_pass(Renderer& renderer, const RenderSettings& render,
                                             const ShadowSettings& shadow, int frames,
                                             std::size_t shape);
// The shape such a measurement moves: the scene's first that is not a
// plane (planes are grounds and walls), or nullopt.
std::optional<std::size_t> movable_shape(const Scene& scene);

// Software rasterizers run compute dispatches outside their timer queries
// (llvmpipe's read near 0 across them): there only the serialized wall
// clock measures the passes. On a GPU the timers do, without the latency
// of a round trip that the wall clock adds to every pass.
bool timers_miss_compute(const std::string& renderer);

// Whether the renderer runs on the CPU (llvmpipe, softpipe, SwiftShader):
// its "GPU times" are times of emulation on the CPU.
bool is_software_renderer(std::string_view renderer);

// The filter passes' median times as multiples of the copy's.
struct CopyRatios {
  const char* clock = "timer";
  std::vector<std::pair<std::string, double>> values;
};
CopyRatios copy_ratios(const PassTimes& times, bool timer_clock);

}  // namespace penumbra
