#pragma once
// `penumbra compare`: every chosen technique on one scene and light,
// measured against the ray-traced reference (and, for the filtered
// techniques, against the filtered hard shadow they approximate); prints a
// table, optionally writes the numbers as JSON and the images (technique,
// references, error maps) into a folder.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/scene_options.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {

struct CompareArgs {
  std::string scene = "default";
  std::string model;           // --model: instead of --scene
  int camera_index = -1;       // --camera-index: a glTF scene's camera
  bool ground = false;         // --ground: a ground under a glTF scene without one
  std::string light;           // --light: one light of this type alone (empty: the scene's lights)
  SceneOptions scene_options;  // camera and light changes, as `render` takes them
  std::string techniques = "all";
  std::string filters = "gaussian";
  std::string output_dir;  // images; none when empty
  std::string json;        // the numbers for scripts; none when empty
  std::string cache_dir;   // traced references; default_cache_dir() when empty
  bool cache = true;       // reuse a cached traced reference
  bool verbose = false;
  // --by-distance: the table also measures the near and far halves of the
  // compared pixels (reference/distance_halves.hpp); the JSON always does.
  bool by_distance = false;
  std::string shadow_maps = "cascades";  // --shadow-maps, parsed into shadow.shadow_maps
  RenderSettings render;
  ShadowSettings shadow;
  ReferenceSettings reference;
};

void add_compare_command_options(CLI::App& command, CompareArgs& args);

// Runs the comparison; throws UsageError or RuntimeError. Every usage
// error is found before anything is written.
int run_compare_command(CompareArgs& args);

}  // namespace penumbra
