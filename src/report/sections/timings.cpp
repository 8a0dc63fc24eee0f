#include "report/study_run.hpp"

#include <algorithm>
#include <array>
#include <iterator>

#include "render/pass_timing.hpp"
#include "report/ranking.hpp"
#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

constexpr Technique kTimedTechniques[] = {
    Technique::Hard, Technique::Pcf, Technique::Pcss,  Technique::Backprojection, Technique::Vsm,
    Technique::Esm,  Technique::Msm, Technique::Msm16, Technique::Evsm2,          Technique::Evsm4};
// One timed frame per technique: every pass of it timed once (`penumbra
// bench --frames N` gives the median and spread of many). No warm-up
// frame: section 1 rendered every technique at these settings with the
// same renderer, so its programs are compiled.
constexpr int kTimedFrames = 1;
constexpr int kWarmupFrames = 0;

// A technique's frames, each with the copy yardstick: about two frames'
// work each.
constexpr int timed_technique_weight() {
  return 2 * (kTimedFrames + kWarmupFrames);
}

}  // namespace

int Study::timings_items() const {
  return static_cast<int>(std::size(kTimedTechniques)) * timed_technique_weight();
}

void Study::timings_section(HtmlPage& page) {
  section(page, "timings", "9. GPU time and memory traffic per pass");
  const bool timer = !timers_miss_compute(context_.renderer());
  page.paragraph(
      "Device: " + context_.renderer() + " (" + context_.vendor() + ", " + context_.version() +
      "). One frame per technique (its shaders compiled for section 1), at " +
      std::to_string(base_render_.width) + "x" + std::to_string(base_render_.height) + " with a " +
      std::to_string(base_shadow_.map_size) + "^2 map, passes serialized, in ms (" +
      (timer ? "GPU timer queries"
             : "wall clock: this renderer's timer queries miss compute work") +
      "). The last column puts each filter pass against a compute copy of the same map (one "
      "read, one write per texel): the filters are memory-bound, so that ratio says how close "
      "they come to the bandwidth limit. `penumbra bench` measures more (the median and "
      "spread of many frames). Passes no technique "
      "ran are left out." +
      (is_software_renderer(context_.renderer())
           ? " This renderer emulates the GPU on the CPU: its times rank the techniques' "
             "work, not what a GPU would take."
           : ""));
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header = {"technique"};
  for (std::size_t p = 0; p < kPassCount; ++p) header.emplace_back(gl::kGpuPassNames[p]);
  header.emplace_back("total");
  header.emplace_back("filters / copy");
  rows.push_back(header);
  for (Technique t : kTimedTechniques) {
    step(timed_technique_weight());
    // Each technique's frame makes its own filtered maps (as the first of
    // each format did anyway), so the section's peak is one technique's
    // maps, not all of theirs (msm's four 2048^2 layers of RGBA32F beside
    // msm16's and evsm4's).
    renderer_.release_filtered_maps();
    try {
      const PassTimes times =
          measure_pass_times(renderer_, base_render_, with(t), kTimedFrames, kWarmupFrames);
      check_gl();
      std::vector<std::string> row = {name_of(t)};
      for (std::size_t p = 0; p < kPassCount; ++p) {
        const Samples& s = times.passes[p];
        row.push_back(times.ran[p] ? fixed(spread_of(timer ? s.timer_ms : s.wall_ms).median, 2)
                                   : "");
      }
      const double total = spread_of(timer ? times.total.timer_ms : times.total.wall_ms).median;
      row.push_back(fixed(total, 2));
      total_ms_.push_back({name_of(t), total});
      std::string ratios;
      for (const auto& [name, ratio] : copy_ratios(times, timer).values) {
        ratios += (ratios.empty() ? "" : ", ") + name + " " + fixed(ratio, 1) + "x";
      }
      row.push_back(ratios);
      rows.push_back(row);
    } catch (const std::exception& e) {
      ++failed_;
      rows.push_back({name_of(t), std::string("failed: ") + e.what()});
    }
  }
  page.table(rows);
  quality_cost_plot(page);
  traffic_plot(page);
}

// RMSE against GPU time, one point per technique timed and measured; the
// settings no other beats in both marked as the Pareto front.
void Study::quality_cost_plot(HtmlPage& page) {
  std::vector<std::string> names;
  std::vector<CostQuality> points;
  for (const auto& [name, ms] : total_ms_) {
    for (const MeasuredError& e : errors_) {
      if (e.label != name) continue;
      names.push_back(name);
      points.push_back({ms, e.traced.rmse});
    }
  }
  const std::vector<std::size_t> front = pareto_front(points);
  const bool emulated = is_software_renderer(context_.renderer());
  LinePlot plot{.title = "Quality against cost",
                .x = {emulated ? "frame time on a GPU emulated on the CPU (ms, the table's "
                                 "total; not a GPU ranking)"
                               : "GPU time per frame (ms, the table's total)",
                      false},
                .y = {kRmseLabel, false},
                .series = {{"technique (W = 4)", {}, false}},
                .highlight_name = "Pareto front"};
  std::vector<std::vector<std::string>> data = {
      {"technique", "time (ms)", "RMSE traced", "on the Pareto front"}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    plot.series[0].points.push_back({points[i].cost, points[i].error, names[i], on_front});
    data.push_back(
        {names[i], fixed(points[i].cost, 2), fixed(points[i].error, 4), on_front ? "yes" : "no"});
    if (on_front) findings_.pareto.push_back({names[i], {points[i].cost, points[i].error}});
  }
  page.heading("Quality against cost", 3);
  page.paragraph(
      "Each technique's RMSE against the traced reference (section 6) against its frame time "
      "(the table above). Filled points are the Pareto front: no other technique is both "
      "faster and closer to the reference." +
      std::string(emulated ? " These times are CPU emulation, not a GPU ranking: on this "
                             "renderer every pass runs on the CPU, where arithmetic costs "
                             "what memory traffic costs on a GPU, so the order of the "
                             "techniques can differ on real hardware."
                           : ""));
  page.plot(svg_line_plot(plot), data);
}

// The bytes each pass over the shadow-map array moves per texel, from the
// passes' own formats, tiles and aprons (the accounting `penumbra bench`
// divides by the measured time).
void Study::traffic_plot(HtmlPage& page) {
  struct Setting {
    std::string name;
    ShadowSettings shadow;
  };
  std::vector<Setting> settings;
  for (Technique t : {Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                      Technique::Evsm2, Technique::Evsm4}) {
    settings.push_back({name_of(t), with(t)});
  }
  settings.push_back({"vsm --soft", soft(Technique::Vsm)});
  settings.push_back({"msm --soft", soft(Technique::Msm)});
  const int size = base_shadow_.map_size;
  std::vector<std::array<std::optional<TexelTraffic>, kPassCount>> traffic;
  std::array<bool, kPassCount> used{};
  for (const Setting& s : settings) {
    traffic.push_back(shadow_map_traffic(s.shadow, size, size));
    for (std::size_t p = 0; p < kPassCount; ++p) used[p] = used[p] || traffic.back()[p];
  }
  // The copy is the yardstick the table compares with, not a pass of the
  // techniques.
  used[static_cast<std::size_t>(gl::GpuPass::BandwidthCopy)] = false;
  StackedBars bars{.title = "Memory traffic per shadow-map texel",
                   .value_label = "bytes read + written per texel",
                   .categories = {},
                   .stack_names = {},
                   .values = {}};
  std::vector<std::vector<std::string>> data = {{"setting", "map bytes / texel"}};
  for (std::size_t p = 0; p < kPassCount; ++p) {
    if (!used[p]) continue;
    bars.stack_names.emplace_back(gl::kGpuPassNames[p]);
    data.front().push_back(std::string(gl::kGpuPassNames[p]) + " (read + written)");
  }
  data.front().emplace_back("total");
  for (std::size_t i = 0; i < settings.size(); ++i) {
    bars.categories.push_back(settings[i].name);
    bars.values.emplace_back();
    std::vector<std::string> row = {
        settings[i].name, std::to_string(map_bytes_per_texel(settings[i].shadow.technique))};
    double total = 0.0;
    for (std::size_t p = 0; p < kPassCount; ++p) {
      if (!used[p]) continue;
      const double bytes = traffic[i][p] ? traffic[i][p]->total() : 0.0;
      bars.values.back().push_back(bytes);
      total += bytes;
      row.push_back(traffic[i][p] ? plot_number(traffic[i][p]->read) + " + " +
                                        plot_number(traffic[i][p]->written)
                                  : "");
    }
    row.push_back(plot_number(total));
    data.push_back(row);
  }
  page.heading("Bytes per texel per pass", 3);
  page.paragraph(
      "The bytes each pass over the " + std::to_string(size) +
      "^2 shadow-map array reads and "
      "writes per texel, counted from its formats, tiles and aprons, every texel a workgroup "
      "loads taken as a read from memory (include/penumbra/shadow/texel_traffic.hpp). On a GPU "
      "the filters "
      "are memory-bound, so these bytes set their cost. The depth-testing techniques (hard, "
      "pcf, pcss) run no pass over the map after the depth pass.");
  page.plot(svg_stacked_bars(bars), data);
}

}  // namespace penumbra
