#pragma once
// Measuring every pass of a frame over several frames: the numbers of
// `penumbra bench` and of the report's timing table.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/settings.hpp"
#include "filter/texture_copy_pass.hpp"
#include "gl/gpu_profiler.hpp"
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

struct PassTimes {
  ShadowSettings shadow;
  std::array<Samples, kPassCount> passes;
  std::array<bool, kPassCount> ran{};
  Samples total;
};

// Renders warmup + frames frames, each followed by the bandwidth yardstick
// (a copy of light 0's map), with a serializing profiler, and keeps the
// times of the last `frames`. Throws RuntimeError on a GL error.
PassTimes measure_pass_times(Renderer& renderer, const RenderSettings& render,
                             const ShadowSettings& shadow, int frames, int warmup);

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
