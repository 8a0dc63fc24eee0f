#include "report/verdict.hpp"

#include <algorithm>

#include "core/number_text.hpp"
#include "report/ranking.hpp"

namespace penumbra {

NamedValue least_named(const std::vector<NamedValue>& values, int digits) {
  std::vector<double> v;
  for (const auto& [name, value] : values) v.push_back(value);
  const std::vector<std::size_t> best = least_at_precision(v, digits);
  std::vector<std::string> names;
  for (std::size_t i : best) names.push_back(values[i].first);
  return {join_names(names) + (names.size() > 1 ? " (tied)" : ""),
          best.empty() ? 0.0 : v[best.front()]};
}

std::vector<VerdictLine> verdict_lines(const StudyFindings& f) {
  std::vector<VerdictLine> lines;
  if (!f.rmse.empty()) {
    const auto [name, rmse] = least_named(f.rmse, 4);
    lines.push_back(
        {"Closest to the ray-traced truth overall", name, "RMSE ", fixed(rmse, 4),
         " against the traced reference (W = 4, light size " + fixed(f.light_size, 2) + ").",
         "errors", "section 6"});
  }
  if (!f.contact_mae.empty()) {
    const auto [name, mae] = least_named(f.contact_mae, 4);
    lines.push_back({"Hard contact shadows", name, "mean error ", fixed(mae, 4),
                     " in the contact-shadow close-up, the least of the single-frame "
                     "techniques.",
                     "closeups", "section 7"});
  }
  if (!f.widest_light_rmse.empty()) {
    const auto [name, rmse] = least_named(f.widest_light_rmse, 4);
    lines.push_back({"Wide soft light", name, "RMSE ", fixed(rmse, 4),
                     " at light size " + fixed(f.widest_light_size, 2) +
                         ", the widest measured, the least of the soft techniques.",
                     "sweeps", "section 4"});
  }
  if (!f.rmse.empty() && f.map_bytes.size() == f.rmse.size()) {
    const int fewest = *std::min_element(f.map_bytes.begin(), f.map_bytes.end());
    std::vector<NamedValue> smallest;
    for (std::size_t i = 0; i < f.rmse.size(); ++i) {
      if (f.map_bytes[i] == fewest) smallest.push_back(f.rmse[i]);
    }
    const auto [name, rmse] = least_named(smallest, 4);
    lines.push_back({"Tight memory budget", name, "RMSE ", fixed(rmse, 4),
                     ", the least of the techniques whose map holds " + std::to_string(fewest) +
                         " bytes per texel, the fewest.",
                     "errors", "section 6"});
  }
  if (!f.directional_rmse.empty()) {
    const auto [name, rmse] = least_named(f.directional_rmse, 4);
    lines.push_back({"Large scenes (a sun over cascades)", name, "RMSE ", fixed(rmse, 4),
                     " under the directional light's " + std::to_string(f.cascades) + " cascades.",
                     "lights", "section 2"});
  }
  if (!f.pareto.empty()) {
    // The cheapest point of the front within twice the front's least error:
    // most of the quality for the least time.
    double best = f.pareto.front().second.second;
    for (const auto& entry : f.pareto) best = std::min(best, entry.second.second);
    const auto* cheapest = &f.pareto.front();
    for (const auto& entry : f.pareto) {
      const bool good = entry.second.second <= 2.0 * best;
      const bool cheapest_good = cheapest->second.second <= 2.0 * best;
      if (good && (!cheapest_good || entry.second.first < cheapest->second.first)) {
        cheapest = &entry;
      }
    }
    // Times from a GPU emulated on the CPU rank the techniques' work on
    // that CPU, which is not how a GPU ranks them (its filters are
    // memory-bound): the line says so where it is read.
    lines.push_back({f.software_times
                         ? "Most quality per millisecond (CPU emulation, not a GPU ranking)"
                         : "Most quality per millisecond",
                     cheapest->first, "", fixed(cheapest->second.first, 2),
                     " ms a frame for RMSE " + fixed(cheapest->second.second, 4) +
                         ": the cheapest point on the Pareto front within twice its least error" +
                         (f.software_times ? ", timed on a GPU emulated on the CPU." : "."),
                     "timings", "section 9"});
  }
  if (f.foliage) lines.push_back(*f.foliage);
  return lines;
}

}  // namespace penumbra
