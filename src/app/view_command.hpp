#pragma once
// `penumbra view`: the interactive viewer. A window shows the scene as
// `render` would write it, with a panel that edits every shared setting,
// the light and the camera; the mouse moves the camera and the light.
#include <CLI/CLI.hpp>
#include <string>

#include "app/options.hpp"
#include "app/scene_options.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {

struct ViewArgs {
  std::string scene = "default";
  std::string model;      // --model: instead of --scene
  int camera_index = -1;  // --camera-index: a glTF scene's camera
  bool ground = false;    // --ground: a ground under a glTF scene without one
  std::string light;      // --light: one light of this type alone (empty: the scene's lights)
  bool verbose = false;
  RenderSettings render;  // width and height: the 3D view's start size
  ShadowSettings shadow;
  SsaoSettings ssao;
  NamedOptions named;
  SceneOptions scene_options;
  // Scripted mode: render this many frames without reading the mouse or
  // keys, then close (0: run until the window closes).
  int frames = 0;
  // Written when the window closes: the last frame's view as `render`
  // writes it, and the whole window (panel included) as PNG.
  std::string screenshot;
  std::string capture_window;
};

void add_view_command_options(CLI::App& command, ViewArgs& args);

// Runs the viewer; throws UsageError or RuntimeError (no display, no
// OpenGL 4.5 context).
int run_view_command(ViewArgs& args);

}  // namespace penumbra
