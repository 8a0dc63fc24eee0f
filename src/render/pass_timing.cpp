#include "render/pass_timing.hpp"

#include <algorithm>

namespace penumbra {

using gl::GpuPass;

Spread spread_of(std::vector<double> values) {
  Spread s;
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  s.min = values.front();
  s.max = values.back();
  return s;
}

PassTimes measure_pass_times(Renderer& renderer, const RenderSettings& render,
                             const ShadowSettings& shadow, int frames, int warmup) {
  TextureCopyPass copy;
  gl::GpuProfiler profiler(2, /*serialize=*/true);
  PassTimes run;
  run.shadow = shadow;
  for (int frame = 0; frame < warmup + frames; ++frame) {
    profiler.begin_frame();
    renderer.render(render, shadow, {}, &profiler);
    {
      gl::GpuPassScope timed(&profiler, GpuPass::BandwidthCopy);
      copy.execute(renderer.shadow_maps());
    }
    profiler.end_frame();
    // Waiting here keeps frames from overlapping, so each pass is timed
    // alone; a benchmark may wait, a frame loop does not.
    std::optional<gl::GpuFrameTimes> times = profiler.read(true);
    if (!times || frame < warmup) continue;
    for (std::size_t p = 0; p < kPassCount; ++p) {
      if (!times->ran[p]) continue;
      run.ran[p] = true;
      run.passes[p].timer_ms.push_back(times->pass_ms[p]);
      run.passes[p].wall_ms.push_back(times->pass_wall_ms[p]);
    }
    run.total.timer_ms.push_back(times->total_ms);
    run.total.wall_ms.push_back(times->total_wall_ms);
  }
  return run;
}

bool is_software_renderer(std::string_view renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "SwiftShader"}) {
    if (renderer.find(software) != std::string_view::npos) return true;
  }
  return false;
}

bool timers_miss_compute(const std::string& renderer) {
  return is_software_renderer(renderer);
}

CopyRatios copy_ratios(const PassTimes& run, bool timer) {
  CopyRatios r;
  const Samples& copy = run.passes[static_cast<std::size_t>(GpuPass::BandwidthCopy)];
  r.clock = timer ? "timer" : "wall";
  const double copy_ms = spread_of(timer ? copy.timer_ms : copy.wall_ms).median;
  if (copy_ms <= 0.0) return r;
  for (GpuPass p : {GpuPass::FusedFilter, GpuPass::FilterHorizontal, GpuPass::FilterVertical,
                    GpuPass::SatRows, GpuPass::SatColumns}) {
    const auto i = static_cast<std::size_t>(p);
    if (!run.ran[i]) continue;
    const Samples& s = run.passes[i];
    r.values.emplace_back(std::string(gl::kGpuPassNames[i]),
                          spread_of(timer ? s.timer_ms : s.wall_ms).median / copy_ms);
  }
  return r;
}

}  // namespace penumbra
