#pragma once
// `penumbra render`: one image of a scene.
#include <CLI/CLI.hpp>
#include <string>

#include "app/options.hpp"
#include "app/scene_options.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {

struct RenderArgs {
  std::string scene = "default";
  std::string model;      // --model: instead of --scene
  int camera_index = -1;  // --camera-index: a glTF scene's camera
  bool ground = false;    // --ground: a ground under a glTF scene without one
  std::string light;      // --light: one light of this type alone (empty: the scene's lights)
  std::string output;
  bool verbose = false;
  bool quiet = false;  // --quiet: no "wrote ..." line on success
  RenderSettings render;
  ShadowSettings shadow;
  SsaoSettings ssao;
  NamedOptions named;
  SceneOptions scene_options;
};

void add_render_command_options(CLI::App& command, RenderArgs& args);

// Renders and writes the image; throws UsageError or RuntimeError.
int run_render_command(RenderArgs& args);

}  // namespace penumbra
