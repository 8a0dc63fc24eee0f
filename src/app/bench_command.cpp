#include "app/bench_command.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/scene_source.hpp"
#include "core/error.hpp"
#include "gl/context.hpp"
#include "gl/gpu_profiler.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "render/pass_timing.hpp"
#include "render/renderer.hpp"
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
  for (Technique t : techniques) {
    for (int v : values) {
      ShadowSettings s = args.shadow;
      s.technique = t;
      if (args.sweep == "map-size") s.map_size = v;
      if (args.sweep == "blur") s.blur = v;
      if (t == Technique::Esm && s.filter == Filter::Sat) continue;  // refused by validate()
      // Soft only for the techniques that can be; a wrong filter is still refused.
      if (s.soft && !supports_soft_shadows(t, Filter::Sat)) s.soft = false;
      runs.push_back(s);
    }
  }
  if (runs.empty()) throw UsageError("nothing to measure: esm cannot use --filter sat");
  return runs;
}

std::string describe(const ShadowSettings& s) {
  std::ostringstream out;
  out << enum_name<Technique>(kTechniqueNames, s.technique);
  if (is_filterable(s.technique)) {
    out << " " << enum_name<Filter>(kFilterNames, s.filter) << " W=" << s.blur
        << (s.soft ? " soft" : "");
  }
  out << ", map " << s.map_size;
  return out.str();
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
  const CopyRatios ratios = copy_ratios(run, timer);
  for (const auto& [name, ratio] : ratios.values) {
    std::printf("  %-18s %8.2fx the copy (%s)\n", name.c_str(), ratio, ratios.clock);
  }
}

nlohmann::json run_json(const PassTimes& run, int frames, bool timer) {
  nlohmann::json j;
  const ShadowSettings& s = run.shadow;
  j["technique"] = std::string(enum_name<Technique>(kTechniqueNames, s.technique));
  j["filter"] = std::string(enum_name<Filter>(kFilterNames, s.filter));
  j["blur"] = s.blur;
  j["soft"] = s.soft;
  j["shadow_map_size"] = s.map_size;
  j["frames"] = frames;
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
  return j;
}

}  // namespace

void add_bench_command_options(CLI::App& command, BenchArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index);
  add_light_choice_option(command, args.light);
  add_number(command, "frames", args.frames, "frames measured per configuration, after the warm-up",
             1, 100000, OptionGroup::Measurement);
  add_number(command, "warmup", args.warmup, "frames rendered before measuring", 0, 1000,
             OptionGroup::Measurement);
  add_choice(command, "sweep", args.sweep,
             "measure each technique at several values: map-size (512, 1024, 2048, 4096) or blur "
             "(W = 0, 1, 2, 4, 8, 16, 32)",
             {"none", "map-size", "blur"}, OptionGroup::Measurement);
  in_group(command.add_option("--json", args.json, "also write the numbers to this JSON file")
               ->type_name("FILE"),
           OptionGroup::Output);
  add_render_options(command, args.render, args.named);
  add_list(command, "technique", args.techniques, "techniques to measure", technique_names(),
           OptionGroup::Technique, "techniques");
  args.named.filter = std::string(enum_name<Filter>(kFilterNames, args.shadow.filter));
  add_choice(command, "filter", args.named.filter,
             "filter of the vsm, esm, msm and msm16 maps: a separable Gaussian, or a summed-area "
             "table",
             filter_names(), OptionGroup::Filter);
  add_shadow_parameters(command, args.shadow);
  command.footer(examples_footer({
      {"every pass of msm, timed", "penumbra bench"},
      {"three techniques side by side, numbers also as JSON",
       "penumbra bench --technique hard,vsm,msm --json bench.json"},
      {"the cost of the filter width, Gaussian against the summed-area table",
       "penumbra bench --technique vsm --sweep blur --filter sat"},
  }));
}

int run_bench_command(BenchArgs& args) {
  const std::vector<Technique> techniques = parse_technique_list(args.techniques, "--technique");
  args.named.technique = "hard";  // the list is parsed above; the rest as usual
  parse_named_options(args.named, args.shadow, args.render);
  if (!args.json.empty()) check_output_path(args.json);
  const std::vector<ShadowSettings> plan = plan_runs(args, techniques);
  for (const ShadowSettings& s : plan) validate(s);
  validate(args.render);
  Scene scene = resolve_scene_source(args.scene, args.model, args.camera_index);
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
  Renderer renderer(scene);
  std::vector<PassTimes> runs;
  for (const ShadowSettings& settings : plan) {
    PassTimes run = measure_pass_times(renderer, args.render, settings, args.frames, args.warmup);
    if (context->error_count() > 0) {
      throw RuntimeError("OpenGL reported " + std::to_string(context->error_count()) +
                         " error(s); last: " + context->last_error());
    }
    print_run(run, args.frames, timer_clock);
    runs.push_back(std::move(run));
  }

  if (!args.json.empty()) {
    nlohmann::json j;
    j["renderer"] = context->renderer();
    j["vendor"] = context->vendor();
    j["version"] = context->version();
    j["scene"] = scene.name;
    j["width"] = args.render.width;
    j["height"] = args.render.height;
    j["runs"] = nlohmann::json::array();
    for (const PassTimes& run : runs) j["runs"].push_back(run_json(run, args.frames, timer_clock));
    write_file_atomically(args.json, j.dump(2) + "\n");
  }
  return 0;
}

}  // namespace penumbra
