#include "render/pass_timing.hpp"

#include <algorithm>

#include "penumbra/filter/depth_hierarchy_pass.hpp"
#include "penumbra/filter/fused_filter_pass.hpp"
#include "penumbra/filter/gaussian_blur_pass.hpp"
#include "penumbra/filter/mip_chain_pass.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/gl/context.hpp"
#include "penumbra/shadow/moment_resolve_pass.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "penumbra/shared/bindings.h"
#include "render/accumulation.hpp"
#include "render/accumulator.hpp"

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

std::array<std::optional<TexelTraffic>, kPassCount> shadow_map_traffic(const ShadowSettings& shadow,
                                                                       int width, int height,
                                                                       int shared_bytes) {
  std::array<std::optional<TexelTraffic>, kPassCount> traffic{};
  auto set = [&](GpuPass pass, TexelTraffic t) { traffic[static_cast<std::size_t>(pass)] = t; };
  const GLenum depth = ShadowMapPass::kDepthFormat;
  GLenum maps = depth;  // what the frame's shadow_maps() hold, which the copy copies
  if (is_filterable(shadow.technique)) {
    maps = representation_format(shadow.technique);
    const int filter = filter_define(shadow);
    if (!uses_fused_filter(shadow)) {
      set(GpuPass::Resolve,
          MomentResolvePass::texel_traffic(depth, shadow.technique, depth_samples(shadow)));
    }
    if (uses_fused_filter(shadow)) {
      set(GpuPass::FusedFilter,
          FusedFilterPass::texel_traffic(maps, shadow.blur, width, height, shared_bytes,
                                         depth_samples(shadow)));
    } else if (filter == FILTER_GAUSSIAN) {
      set(GpuPass::FilterHorizontal,
          GaussianBlurPass::texel_traffic(maps, shadow.blur, 0, width, height));
      set(GpuPass::FilterVertical,
          GaussianBlurPass::texel_traffic(maps, shadow.blur, 1, width, height));
    } else if (filter == FILTER_SAT) {
      set(GpuPass::SatRows, SummedAreaTablePass::row_traffic(maps));
      set(GpuPass::SatColumns, SummedAreaTablePass::column_traffic(maps));
    }
    if (uses_shadow_mips(shadow)) {
      set(GpuPass::Mips, MipChainPass::texel_traffic(maps, width, height,
                                                     filtered_map_levels(shadow, width, height)));
    }
  }
  if (shadow.technique == Technique::Backprojection) {
    set(GpuPass::DepthHierarchy, DepthHierarchyPass::texel_traffic(depth, width, height));
  }
  if (shadow.technique != Technique::None) {
    set(GpuPass::BandwidthCopy, TextureCopyPass::texel_traffic(maps));
  }
  return traffic;
}

double median_ms(const Samples& samples, bool timer_clock) {
  return spread_of(timer_clock ? samples.timer_ms : samples.wall_ms).median;
}

double converged_image_ms(const PassTimes& run, bool timer_clock) {
  double camera = 0.0;
  for (const gl::GpuPass pass : {gl::GpuPass::GBuffer, gl::GpuPass::AmbientOcclusion}) {
    const auto p = static_cast<std::size_t>(pass);
    if (run.ran[p]) camera += median_ms(run.passes[p], timer_clock);
  }
  const double frame = median_ms(run.total, timer_clock);
  return camera + std::max(run.shadow.accumulate, 1) * (frame - camera);
}

double achieved_gb_per_second(const PassTimes& run, std::size_t pass, bool timer_clock) {
  const double ms = median_ms(run.passes[pass], timer_clock);
  if (!run.traffic[pass] || !(ms > 0.0)) return 0.0;
  return run.traffic[pass]->total() * run.texels / (ms * 1e6);
}

PassTimes measure_pass_times(Renderer& renderer, const RenderSettings& render,
                             const ShadowSettings& shadow, int frames, int warmup) {
  TextureCopyPass copy;
  gl::GpuProfiler profiler(2, /*serialize=*/true);
  PassTimes run;
  run.shadow = shadow;
  // With --accumulate N a frame is one sub-frame, added to the sum: the
  // sub-frames cycle through the source's N points, as the viewer's do.
  const bool accumulating = shadow.accumulate > 1 && !is_map_view(render.view);
  const std::vector<Light> lights = renderer.scene().lights;
  std::optional<Accumulator> accumulator;
  if (accumulating) accumulator.emplace();
  for (int frame = 0; frame < warmup + frames; ++frame) {
    // Every frame times every pass, the camera's included (render() would
    // reuse them for the same camera, and the shadow maps for the same
    // lights).
    renderer.forget_surfaces();
    renderer.forget_shadow_maps();
    profiler.begin_frame();
    if (accumulating) {
      render_subframe(renderer, lights, render, shadow, {}, frame % shadow.accumulate, &profiler);
      gl::GpuPassScope timed(&profiler, GpuPass::Accumulate);
      accumulator->add(renderer.view_source());
    } else {
      renderer.render(render, shadow, {}, &profiler);
    }
    // The yardstick copies the frame's shadow maps: none without a
    // technique.
    if (shadow.technique != Technique::None) {
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
  if (accumulating) renderer.set_lights(lights);
  const gl::Texture& maps = renderer.shadow_maps();
  run.texels = static_cast<double>(maps.width()) * maps.height() * maps.layers();
  GLint shared_bytes = 0;
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &shared_bytes);
  run.traffic = shadow_map_traffic(shadow, maps.width(), maps.height(), shared_bytes);
  return run;
}

CachedShadowTimes measure_cached_shadow_pass(Renderer& renderer, const RenderSettings& render,
                                             const ShadowSettings& shadow, int frames,
                                             std::size_t shape) {
  gl::GpuProfiler profiler(2, /*serialize=*/true);
  CachedShadowTimes result;
  result.shape = shape;
  // The passes over the shadow maps: the depth pass through the mip chain.
  auto timed_frame = [&](Samples& into) {
    profiler.begin_frame();
    renderer.render(render, shadow, {}, &profiler);
    profiler.end_frame();
    const std::optional<gl::GpuFrameTimes> times = profiler.read(true);
    if (!times) return;
    double timer_ms = 0.0, wall_ms = 0.0;
    for (std::size_t p = 0; p <= static_cast<std::size_t>(GpuPass::Mips); ++p) {
      if (!times->ran[p]) continue;
      timer_ms += times->pass_ms[p];
      wall_ms += times->pass_wall_ms[p];
    }
    into.timer_ms.push_back(timer_ms);
    into.wall_ms.push_back(wall_ms);
  };
  const Bounds bounds = renderer.shape_bounds(shape);
  const glm::vec3 step(0.05f * std::max(bounds.max.x - bounds.min.x, 1e-3f), 0.0f, 0.0f);
  renderer.render(render, shadow);  // shaders compiled, maps drawn
  for (int frame = 0; frame < frames; ++frame) {
    renderer.forget_shadow_maps();
    timed_frame(result.full);
    result.views = std::max(result.views, renderer.shadow_views_drawn());
    timed_frame(result.still);
    result.still_views = std::max(result.still_views, renderer.shadow_views_drawn());
    renderer.move_shape(shape, frame % 2 == 0 ? step : -step);
    timed_frame(result.moving);
    result.moving_views = std::max(result.moving_views, renderer.shadow_views_drawn());
  }
  if (frames % 2 == 1) renderer.move_shape(shape, -step);  // back where it was
  return result;
}

std::optional<std::size_t> movable_shape(const Scene& scene) {
  for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
    if (scene.shapes[i].kind != ShapeKind::Plane) return i;
  }
  return std::nullopt;
}

bool is_software_renderer(std::string_view renderer) {
  return gl::is_cpu_rasterizer(renderer);
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
                    GpuPass::SatRows, GpuPass::SatColumns, GpuPass::Mips}) {
    const auto i = static_cast<std::size_t>(p);
    if (!run.ran[i]) continue;
    const Samples& s = run.passes[i];
    r.values.emplace_back(std::string(gl::kGpuPassNames[i]),
                          spread_of(timer ? s.timer_ms : s.wall_ms).median / copy_ms);
  }
  return r;
}

}  // namespace penumbra
