#pragma once
// The `penumbra render` command that re-makes a view headless: what the
// viewer's "Copy as command" gives. It names only what differs from the
// defaults, with the flag names the CLI registers.
#include <string>
#include <vector>

#include "penumbra/settings.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct RenderCommand {
  std::string scene_argument;  // as given to --scene
  std::string model_argument;  // as given to --model (then the scene is ignored)
  std::string light;           // as given to --light (empty: not given)
  int camera_index = -1;       // as given to --camera-index (-1: not given)
  bool ground = false;         // as given to --ground
  RenderSettings render;
  ShadowSettings shadow;
  SsaoSettings ssao;
  // The scene as loaded, and with its camera and lights as shown.
  const Scene* original = nullptr;
  const Scene* edited = nullptr;
  std::string output;
};

// The arguments after the program name, starting with "render".
std::vector<std::string> render_command_args(const RenderCommand& command);

// "penumbra render ...": the arguments quoted for a POSIX shell.
std::string shell_command(const std::vector<std::string>& args);

}  // namespace penumbra
