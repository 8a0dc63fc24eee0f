#pragma once
// `penumbra bench`: GPU time of every pass, per technique, with a
// bandwidth yardstick, and sweeps of the map size and the filter width.
#include <CLI/CLI.hpp>
#include <string>

#include "app/options.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {

struct BenchArgs {
  std::string scene = "default";
  std::string model;      // --model: instead of --scene
  int camera_index = -1;  // --camera-index: a glTF scene's camera
  bool ground = false;    // --ground: a ground under a glTF scene without one
  std::string light;      // --light: one light of this type alone (empty: the scene's lights)
  std::string techniques = "msm";  // a name, a comma-separated list, or "all"
  std::string sweep = "none";      // none, map-size or blur
  int frames = 20;
  int warmup = 3;
  float bandwidth = 0.0f;  // --bandwidth, GB/s (0: from the table of known GPUs)
  std::string json;
  RenderSettings render;
  ShadowSettings shadow;
  NamedOptions named;
};

void add_bench_command_options(CLI::App& command, BenchArgs& args);

// Throws UsageError or RuntimeError.
int run_bench_command(BenchArgs& args);

}  // namespace penumbra
