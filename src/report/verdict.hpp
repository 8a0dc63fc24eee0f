#pragma once
// The report's "which technique when": each line picked from numbers the
// study measured, written as the sections print them, ties named as ties.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/html_page.hpp"

namespace penumbra {

using NamedValue = std::pair<std::string, double>;

// What the study measured that the verdict draws on; an empty list leaves
// its line out.
struct StudyFindings {
  float light_size = 0.0f;  // of the spot light the errors are measured under
  int cascades = 0;
  // Single-frame settings (W = 4): RMSE against the traced reference, and
  // the bytes per texel of the map each one's lookup reads.
  std::vector<NamedValue> rmse;
  std::vector<int> map_bytes;  // parallel to rmse
  // Mean absolute error in the contact-shadow close-up.
  std::vector<NamedValue> contact_mae;
  // The soft techniques' RMSE at the widest light size measured.
  std::vector<NamedValue> widest_light_rmse;
  float widest_light_size = 0.0f;
  // RMSE under the directional light's cascades.
  std::vector<NamedValue> directional_rmse;
  // The Pareto front of GPU time (ms) against RMSE: (name, (ms, rmse)).
  std::vector<std::pair<std::string, std::pair<double, double>>> pareto;
  // The times come from a renderer that emulates the GPU on the CPU.
  bool software_times = false;
  // A foliage section's line, when the report has one.
  std::optional<VerdictLine> foliage;
};

// The names of the least values at `digits` decimals ("a and b (tied)"),
// and that value.
NamedValue least_named(const std::vector<NamedValue>& values, int digits);

std::vector<VerdictLine> verdict_lines(const StudyFindings& findings);

}  // namespace penumbra
