#include "app/bench_command.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/options.hpp"
#include "app/scene_source.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/progress_bar.hpp"
#include "penumbra/error.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/gl/context.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"
#include "render/device_bandwidth.hpp"
#include "render/pass_timing.hpp"
#include "render/renderer.hpp"
#include "render/virtual_page_orbit.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {

namespace {

using gl::GpuPass;

// The settings of each run: every technique, and the sweep's values.
std::vector<ShadowSettings> plan_runs(const BenchArgs& args,
                                      const std::vector<Technique>& techniques) {
  std::vector<ShadowSettings> runs;
  std::vector<int> values = {0};
  if (args.sweep == "map-size") values = {512, 1024, 2048, 4096};
  if (args.sweep == "blur") values = {0, 1, 2, 4, 8, 16, 32};
  if (args.sweep == "fused") values = {1, 0};
  if (args.sweep == "msaa") values = {1, 2, 4, 8};
  for (Technique t : techniques) {
    for (int v : values) {
      ShadowSettings s = args.shadow;
      s.technique = t;
      if (args.sweep == "map-size") s.map_size = v;
      if (args.sweep == "blur") s.blur = v;
      if (args.sweep == "fused") s.fused = v == 1;
      if (args.sweep == "msaa") s.shadow_msaa = v;
      // Maps of depth are drawn with one sample whatever --shadow-msaa says.
      if (depth_samples(s) != s.shadow_msaa && v > 1) continue;
      if (is_filterable(t) && !supports_sat(t) && s.filter == Filter::Sat) continue;  // refused
      // Soft only for the techniques that can be; a wrong filter is still refused.
      if (s.soft && !supports_soft_shadows(t, Filter::Sat)) s.soft = false;
      runs.push_back(s);
    }
  }
  if (runs.empty()) throw UsageError("nothing to measure: esm and evsm cannot use --filter sat");
  return runs;
}

std::string describe(const ShadowSettings& s) {
  std::ostringstream out;
  out << enum_name<Technique>(kTechniqueNames, s.technique);
  if (is_filterable(s.technique)) {
    out << " " << enum_name<Filter>(kFilterNames, s.filter) << " W=" << s.blur
        << (s.soft ? " soft" : "");
    // Which path filtered: --fused on falls back past the fused pass's reach.
    if (filter_define(s) == FILTER_GAUSSIAN) out << (uses_fused_filter(s) ? " fused" : " two-pass");
    if (uses_shadow_mips(s)) out << " mips";
    out << " (" << format_name(representation_format(s.technique)) << ")";
  }
  out << ", map " << s.map_size;
  if (s.shadow_maps == ShadowMapKind::Virtual) {
    out << ", virtual maps for the sun and spots (pool " << s.page_pool_mib << " MiB)";
  }
  if (depth_samples(s) > 1) out << ", msaa " << depth_samples(s);
  if (s.accumulate > 1) out << ", accumulate " << s.accumulate << " (a frame is one sub-frame)";
  return out.str();
}

// The device's memory bandwidth, where known: the floor of a pass is its
// bytes at that rate.
struct Bandwidth {
  double gb_per_second = 0.0;  // 0: unknown
  std::string source;          // where the figure comes from
};

Bandwidth device_bandwidth(const BenchArgs& args, const std::string& renderer) {
  if (args.bandwidth > 0.0f) return {args.bandwidth, "--bandwidth"};
  if (const std::optional<DeviceBandwidth> known = known_device_bandwidth(renderer)) {
    return {known->gb_per_second, "NVIDIA " + std::string(known->part) + " data sheet"};
  }
  return {};
}

// Each pass over the shadow maps: its bytes per texel, the bandwidth it
// achieved, and its floor at the device's bandwidth.
void print_traffic(const PassTimes& run, bool timer, const Bandwidth& bandwidth) {
  std::printf("  bytes per shadow-map texel (%.2f M texels a frame)", run.texels * 1e-6);
  if (bandwidth.gb_per_second > 0.0) {
    std::printf("; floor at %.0f GB/s (%s)", bandwidth.gb_per_second, bandwidth.source.c_str());
  }
  std::printf(":\n  %-18s %7s %8s %7s %10s", "pass", "read", "written", "total", "GB/s");
  if (bandwidth.gb_per_second > 0.0) std::printf(" %10s %8s", "floor ms", "x floor");
  std::printf("\n");
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (!run.ran[p] || !run.traffic[p]) continue;
    const TexelTraffic& t = *run.traffic[p];
    const std::string_view name = gl::kGpuPassNames[p];
    std::printf("  %-18.*s %7.2f %8.2f %7.2f %10.2f", static_cast<int>(name.size()), name.data(),
                t.read, t.written, t.total(), achieved_gb_per_second(run, p, timer));
    if (bandwidth.gb_per_second > 0.0) {
      const double floor_ms = t.total() * run.texels / (bandwidth.gb_per_second * 1e6);
      std::printf(" %10.4f %8.2f", floor_ms, median_ms(run.passes[p], timer) / floor_ms);
    }
    std::printf("\n");
  }
}

void print_run(const PassTimes& run, int frames, bool timer) {
  std::printf("\n%s (%d frames; ms: median [min, max])\n", describe(run.shadow).c_str(), frames);
  std::printf("  %-18s %27s %27s\n", "pass", "GPU timer queries", "wall clock, serialized");
  auto row = [](std::string_view name, const Samples& samples) {
    const Spread t = spread_of(samples.timer_ms), w = spread_of(samples.wall_ms);
    std::printf("  %-18.*s %9.3f [%7.3f, %7.3f] %9.3f [%7.3f, %7.3f]\n",
                static_cast<int>(name.size()), name.data(), t.median, t.min, t.max, w.median, w.min,
                w.max);
  };
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (run.ran[p]) row(gl::kGpuPassNames[p], run.passes[p]);
  }
  row("total (frame)", run.total);
  if (run.shadow.accumulate > 1) {
    const int n = run.shadow.accumulate;
    std::printf(
        "  a converged image (%d sub-frames, the camera's passes once): %.3f ms by the timers, "
        "%.3f by the wall clock\n",
        n, converged_image_ms(run, true), converged_image_ms(run, false));
  }
  const CopyRatios ratios = copy_ratios(run, timer);
  for (const auto& [name, ratio] : ratios.values) {
    std::printf("  %-18s %8.2fx the copy (%s)\n", name.c_str(), ratio, ratios.clock);
  }
}

nlohmann::json run_json(const PassTimes& run, int frames, bool timer, const Bandwidth& bandwidth) {
  nlohmann::json j;
  const ShadowSettings& s = run.shadow;
  j["technique"] = std::string(enum_name<Technique>(kTechniqueNames, s.technique));
  j["filter"] = std::string(enum_name<Filter>(kFilterNames, s.filter));
  j["blur"] = s.blur;
  j["soft"] = s.soft;
  j["shadow_map_size"] = s.map_size;
  j["shadow_maps"] = std::string(enum_name<ShadowMapKind>(kShadowMapKindNames, s.shadow_maps));
  j["page_pool_mib"] = s.page_pool_mib;
  j["tight_cascades"] = s.tight_cascades;
  j["shadow_msaa"] = depth_samples(s);  // the samples drawn per texel
  j["fused"] = is_filterable(s.technique) && uses_fused_filter(s);
  j["shadow_mips"] = uses_shadow_mips(s);
  if (is_filterable(s.technique)) {
    j["representation_format"] = format_name(representation_format(s.technique));
  }
  j["frames"] = frames;
  // With --accumulate N each frame is one sub-frame; N of them make the
  // converged image, which draws the camera's passes once.
  j["accumulate"] = s.accumulate;
  j["converged_image_ms"] = converged_image_ms(run, true);
  j["converged_image_wall_ms"] = converged_image_ms(run, false);
  auto samples_json = [](const Samples& samples) {
    const Spread t = spread_of(samples.timer_ms), w = spread_of(samples.wall_ms);
    return nlohmann::json{{"median_ms", t.median}, {"min_ms", t.min},
                          {"max_ms", t.max},       {"wall_median_ms", w.median},
                          {"wall_min_ms", w.min},  {"wall_max_ms", w.max}};
  };
  nlohmann::json passes = nlohmann::json::object();
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (run.ran[p]) passes[std::string(gl::kGpuPassNames[p])] = samples_json(run.passes[p]);
  }
  j["passes"] = passes;
  j["total"] = samples_json(run.total);
  const CopyRatios ratios = copy_ratios(run, timer);
  j["times_the_copy"] = nlohmann::json::object();
  for (const auto& [name, ratio] : ratios.values) j["times_the_copy"][name] = ratio;
  j["ratio_clock"] = ratios.clock;
  // Bytes per texel of the passes over the shadow maps, the bandwidth
  // each achieved (on the ratios' clock), and its floor at the device's.
  j["texels"] = run.texels;
  j["bytes_per_texel"] = nlohmann::json::object();
  j["gb_per_second"] = nlohmann::json::object();
  j["floor_ms"] = nlohmann::json::object();
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (!run.ran[p] || !run.traffic[p]) continue;
    const TexelTraffic& t = *run.traffic[p];
    const std::string name(gl::kGpuPassNames[p]);
    j["bytes_per_texel"][name] = {{"read", t.read}, {"written", t.written}, {"total", t.total()}};
    j["gb_per_second"][name] = achieved_gb_per_second(run, p, timer);
    j["floor_ms"][name] =
        bandwidth.gb_per_second > 0.0
            ? nlohmann::json(t.total() * run.texels / (bandwidth.gb_per_second * 1e6))
            : nlohmann::json(nullptr);
  }
  return j;
}

// The frames of the cached-maps measurement: medians of a few suffice to
// tell a static frame's nothing from a moving one's views.
constexpr int kMaxCachedFrames = 10;

// The shadow passes of a frame drawing every view, of a static frame and
// of one where a shape moved, on the ratios' clock (the timers miss
// llvmpipe's compute passes).
void print_cached(const CachedShadowTimes& cached, int frames, bool timer) {
  auto median = [timer](const Samples& s) {
    return spread_of(timer ? s.timer_ms : s.wall_ms).median;
  };
  const double full = median(cached.full), still = median(cached.still);
  std::printf(
      "  cached shadow maps (%d frames each; depth + resolve + filters + mips, median ms, %s):\n",
      frames, timer ? "timer" : "wall clock");
  std::printf("  %-34s %9.3f  (%d views drawn)\n", "every view drawn", full, cached.views);
  std::printf("  %-34s %9.3f  (%d views drawn; %.1f %% of every view)\n", "static frame", still,
              cached.still_views, full > 0.0 ? 100.0 * still / full : 0.0);
  std::printf("  %-34s %9.3f  (%d of %d views drawn)\n",
              ("shape " + std::to_string(cached.shape) + " moving").c_str(), median(cached.moving),
              cached.moving_views, cached.views);
}

nlohmann::json cached_json(const CachedShadowTimes& cached, int frames, bool timer) {
  auto samples_json = [](const Samples& samples) {
    const Spread t = spread_of(samples.timer_ms), w = spread_of(samples.wall_ms);
    return nlohmann::json{{"median_ms", t.median}, {"wall_median_ms", w.median}};
  };
  const double full = spread_of(timer ? cached.full.timer_ms : cached.full.wall_ms).median;
  const double still = spread_of(timer ? cached.still.timer_ms : cached.still.wall_ms).median;
  return {{"frames", frames},
          {"views", cached.views},
          {"full", samples_json(cached.full)},
          {"static", samples_json(cached.still)},
          {"static_views_drawn", cached.still_views},
          {"static_fraction_of_full", full > 0.0 ? still / full : 0.0},
          {"moving_shape", cached.shape},
          {"moving", samples_json(cached.moving)},
          {"moving_views_drawn", cached.moving_views}};
}

// The virtual shadow maps' pages under an orbiting camera: frames of the
// orbit, and degrees a frame.
constexpr int kOrbitFrames = 24;
constexpr float kOrbitDegrees = 1.0f;

void print_orbit(const std::vector<VirtualOrbitFrame>& orbit) {
  std::printf("  virtual pages, camera orbiting %.0f degree a frame (pool %d pages):\n",
              static_cast<double>(kOrbitDegrees), orbit.empty() ? 0 : orbit.front().pool_pages);
  std::printf("  %-6s %10s %10s %9s %10s %11s %9s\n", "frame", "allocated", "rendered", "rendered%",
              "pool used%", "page draws", "unculled");
  for (std::size_t f = 0; f < orbit.size(); ++f) {
    const VirtualOrbitFrame& o = orbit[f];
    std::printf("  %-6zu %10d %10d %8.1f%% %9.1f%% %11d %9d\n", f, o.resident, o.rendered,
                o.resident > 0 ? 100.0 * o.rendered / o.resident : 0.0,
                o.pool_pages > 0 ? 100.0 * o.resident / o.pool_pages : 0.0, o.page_draws,
                o.unculled_page_draws);
  }
}

nlohmann::json orbit_json(const std::vector<VirtualOrbitFrame>& orbit) {
  nlohmann::json frames = nlohmann::json::array();
  for (const VirtualOrbitFrame& o : orbit) {
    frames.push_back({{"allocated", o.resident},
                      {"rendered", o.rendered},
                      {"pool_pages", o.pool_pages},
                      {"page_draws", o.page_draws},
                      {"unculled_page_draws", o.unculled_page_draws}});
  }
  return {{"degrees_per_frame", kOrbitDegrees}, {"frames", frames}};
}

// How long the whole plan will take, before it starts: two frames of the
// first configuration, the first of which compiles its shaders as every
// configuration's first frame does; the rest are frames like the second.
// Techniques differ in cost, so this is an estimate, and says so.
void print_estimate(Renderer& renderer, const BenchArgs& args,
                    const std::vector<ShadowSettings>& plan) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const PassTimes probe = measure_pass_times(renderer, args.render, plan.front(), 1, 1);
  const double probe_s = std::chrono::duration<double>(Clock::now() - start).count();
  const double steady_s =
      probe.total.wall_ms.empty() ? probe_s / 2.0 : probe.total.wall_ms.front() * 1e-3;
  const double first_s = std::max(steady_s, probe_s - steady_s);
  const int frames = args.frames + args.warmup;
  const double total_s = static_cast<double>(plan.size()) * (first_s + (frames - 1) * steady_s);
  std::printf(
      "estimate: about %.*f s for %zu configuration%s of %d frames (%d warm-up), from two frames "
      "of the first (%.2f s with its shaders compiled, then %.3f s a frame)\n",
      total_s < 10.0 ? 1 : 0, total_s, plan.size(), plan.size() == 1 ? "" : "s", frames,
      args.warmup, first_s, steady_s);
  flush_standard_output();
}

}  // namespace

void add_bench_command_options(CLI::App& command, BenchArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index, args.ground);
  add_light_choice_option(command, args.light);
  add_number(command, "frames", args.frames, "frames measured per configuration, after the warm-up",
             1, 100000, OptionGroup::Measurement);
  add_number(command, "warmup", args.warmup, "frames rendered before measuring", 0, 1000,
             OptionGroup::Measurement);
  add_choice(command, "sweep", args.sweep,
             "measure each technique at several values: map-size (512, 1024, 2048, 4096), blur "
             "(W = 0, 1, 2, 4, 8, 16, 32), fused (--fused, then --no-fused) or msaa "
             "(--shadow-msaa 1, 2, 4, 8, up to the GPU's limit)",
             {"none", "map-size", "blur", "fused", "msaa"}, OptionGroup::Measurement);
  add_number(command, "bandwidth", args.bandwidth,
             "the GPU's memory bandwidth in GB/s, for each pass's floor (0: from a table of NVIDIA "
             "GPUs; none for others)",
             1.0f, 1e6f, OptionGroup::Measurement);
  in_group(command.add_option("--json", args.json, "also write the numbers to this JSON file")
               ->type_name("FILE"),
           OptionGroup::Output);
  add_render_options(command, args.render, args.named);
  add_list(command, "technique", args.techniques, "techniques to measure", technique_names(),
           OptionGroup::Technique, "techniques");
  args.named.filter = std::string(enum_name<Filter>(kFilterNames, args.shadow.filter));
  add_choice(command, "filter", args.named.filter,
             "filter of the vsm, esm, msm, msm16, evsm2 and evsm4 maps: a separable Gaussian, or a "
             "summed-area table",
             filter_names(), OptionGroup::Filter);
  add_shadow_maps_option(command, args.shadow, args.named.shadow_maps,
                         "; the pages allocated and rendered per frame and the pool's "
                         "occupancy are reported");
  add_shadow_parameters(command, args.shadow);
  add_accumulate_option(command, args.shadow);
  command.footer(examples_footer({
      {"every pass of msm, timed", "penumbra bench"},
      {"three techniques side by side, numbers also as JSON",
       "penumbra bench --technique hard,vsm,msm --json bench.json"},
      {"the cost of the filter width, Gaussian against the summed-area table",
       "penumbra bench --technique vsm --sweep blur --filter sat"},
      {"one sub-frame of accumulated soft shadows, and what 64 of them cost",
       "penumbra bench --technique hard --accumulate 64"},
      {"the source's two soft shadows, with the texels each reads per pixel",
       "penumbra bench --technique pcss,backprojection --light-size 1.5"},
      {"the depth and resolve passes' cost per sample count of multisampled maps",
       "penumbra bench --technique vsm,msm --sweep msaa"},
  }));
}

int run_bench_command(BenchArgs& args) {
  const std::vector<Technique> techniques = parse_technique_list(args.techniques, "--technique");
  args.named.technique = "hard";  // the list is parsed above; the rest as usual
  parse_named_options(args.named, args.shadow, args.render);
  if (!args.json.empty()) check_output_path(args.json);
  std::vector<ShadowSettings> plan = plan_runs(args, techniques);
  for (const ShadowSettings& s : plan) validate(s);
  validate(args.render);
  Scene scene = resolve_scene_source(args.scene, args.model, args.camera_index, args.ground);
  apply_light_choice(args.light, scene);
  check_light_index(args.render.light_index, scene);

  auto context = gl::Context::create_headless();
  std::printf("penumbra bench: %s (%s, %s)\n", context->renderer().c_str(),
              context->vendor().c_str(), context->version().c_str());
  std::printf("scene %s, view %dx%d\n", scene.name.c_str(), args.render.width, args.render.height);

  const bool timer_clock = !timers_miss_compute(context->renderer());
  if (!timer_clock) {
    std::printf("(timer queries miss compute work on this renderer: ratios use the wall clock)\n");
  }
  if (args.sweep == "msaa") {
    // The sweep stops at the device's limit (llvmpipe: 4); an explicit
    // --shadow-msaa beyond it is refused by the first frame instead.
    GLint max_samples = 1;
    glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_samples);
    std::erase_if(plan, [&](const ShadowSettings& s) { return depth_samples(s) > max_samples; });
    std::printf("--sweep msaa: up to %d samples per texel, this GPU's limit for depth textures\n",
                max_samples);
  }
  const Bandwidth bandwidth = device_bandwidth(args, context->renderer());
  const bool parallel_sat = preferred_sat_scan(context->renderer()) == SatScan::Parallel;
  if (std::any_of(plan.begin(), plan.end(),
                  [](const ShadowSettings& s) { return filter_define(s) == FILTER_SAT; })) {
    std::printf("summed-area tables: %s\n", parallel_sat
                                                ? "parallel scans (tiles and carries)"
                                                : "one thread per line (a CPU rasterizer)");
  }
  Renderer renderer(scene);
  print_estimate(renderer, args, plan);
  // One line per configuration on stderr where it is not a terminal (a
  // log shows where the time goes), a bar with the time left where it is.
  ProgressBar progress("bench");
  std::vector<PassTimes> runs;
  std::vector<std::optional<CachedShadowTimes>> cached_runs;
  std::vector<std::optional<std::vector<VirtualOrbitFrame>>> orbits;
  const std::optional<std::size_t> moving = movable_shape(scene);
  const int cached_frames = std::min(args.frames, kMaxCachedFrames);
  // PCSS's and backprojection's texel reads per pixel {min, mean, max}:
  // their work is bounded per pixel, not fixed, so their time depends on
  // the scene (LightingPass::counts_fetches()).
  std::vector<std::optional<std::array<double, 3>>> fetches(plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const ShadowSettings& settings = plan[i];
    progress.step(describe(settings), static_cast<std::int64_t>(i),
                  static_cast<std::int64_t>(plan.size()));
    PassTimes run = measure_pass_times(renderer, args.render, settings, args.frames, args.warmup);
    if (context->error_count() > 0) {
      throw RuntimeError("OpenGL reported " + std::to_string(context->error_count()) +
                         " error(s); last: " + context->last_error());
    }
    print_run(run, args.frames, timer_clock);
    print_traffic(run, timer_clock, bandwidth);
    // An --accumulate sub-frame draws every view from another point of the
    // source: nothing to cache.
    std::optional<CachedShadowTimes> cached;
    if (moving && settings.accumulate == 1 && settings.technique != Technique::None) {
      cached = measure_cached_shadow_pass(renderer, args.render, settings, cached_frames, *moving);
      print_cached(*cached, cached_frames, timer_clock);
    }
    cached_runs.push_back(cached);
    std::optional<std::vector<VirtualOrbitFrame>> orbit;
    if (settings.shadow_maps == ShadowMapKind::Virtual && !renderer.virtual_lights().empty()) {
      orbit = orbit_virtual_pages(renderer, args.render, settings, kOrbitFrames, kOrbitDegrees);
      print_orbit(*orbit);
    }
    orbits.push_back(orbit);
    if (LightingPass::counts_fetches(settings)) {
      fetches[i] = renderer.count_lookup_fetches(args.render, settings);
      std::printf("  %s fetches per pixel: min %.0f, mean %.1f, max %.0f\n",
                  std::string(enum_name<Technique>(kTechniqueNames, settings.technique)).c_str(),
                  (*fetches[i])[0], (*fetches[i])[1], (*fetches[i])[2]);
    }
    // Each result as it is measured, also when stdout is a file (a full
    // device or a closed pipe is an error here, with its reason).
    flush_standard_output();
    runs.push_back(std::move(run));
  }
  progress.finish();

  if (!args.json.empty()) {
    nlohmann::json j;
    j["renderer"] = context->renderer();
    j["vendor"] = context->vendor();
    j["version"] = context->version();
    j["scene"] = scene.name;
    j["width"] = args.render.width;
    j["height"] = args.render.height;
    j["bandwidth_gb_per_second"] = bandwidth.gb_per_second > 0.0
                                       ? nlohmann::json(bandwidth.gb_per_second)
                                       : nlohmann::json(nullptr);
    j["sat_scan"] = parallel_sat ? "parallel" : "serial";
    j["bandwidth_source"] =
        bandwidth.source.empty() ? nlohmann::json(nullptr) : nlohmann::json(bandwidth.source);
    j["runs"] = nlohmann::json::array();
    for (std::size_t i = 0; i < runs.size(); ++i) {
      nlohmann::json run = run_json(runs[i], args.frames, timer_clock, bandwidth);
      run["cached_shadow_maps"] = cached_runs[i]
                                      ? cached_json(*cached_runs[i], cached_frames, timer_clock)
                                      : nlohmann::json(nullptr);
      run["virtual_pages"] = orbits[i] ? orbit_json(*orbits[i]) : nlohmann::json(nullptr);
      if (fetches[i]) {
        run["fetches_per_pixel"] = {
            {"min", (*fetches[i])[0]}, {"mean", (*fetches[i])[1]}, {"max", (*fetches[i])[2]}};
      }
      j["runs"].push_back(std::move(run));
    }
    write_file_atomically(args.json, j.dump(2) + "\n");
  }
  return 0;
}

}  // namespace penumbra
