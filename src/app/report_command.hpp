#pragma once
// `penumbra report`: the whole study as one HTML page with its images.
#include <CLI/CLI.hpp>
#include <string>

namespace penumbra {

struct ReportArgs {
  std::string scene = "default";
  std::string model;      // --model: instead of --scene
  int camera_index = -1;  // --camera-index: a glTF scene's camera
  bool ground = false;    // --ground: a ground under a glTF scene without one
  std::string light;      // --light: one light of this type alone (empty: the scene's lights)
  std::string output;
  bool quick = false;
};

void add_report_command_options(CLI::App& command, ReportArgs& args);

// Throws UsageError or RuntimeError; returns 1 if some items failed (the
// page is still written, and says which).
int run_report_command(const ReportArgs& args);

}  // namespace penumbra
