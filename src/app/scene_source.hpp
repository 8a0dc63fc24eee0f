#pragma once
// Where a command's scene comes from: `--scene` (a built-in name or a JSON
// scene file) or `--model` (a model file framed on a ground plane by
// framed_model_scene). Every command that renders a scene takes both.
#include <CLI/CLI.hpp>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// Registers --scene and --model; giving both is a usage error.
void add_scene_source_options(CLI::App& command, std::string& scene, std::string& model);

// The scene they name: the model's framed scene when `model` is set.
// Throws UsageError for an unknown scene name, RuntimeError for a file that
// cannot be read or parsed.
Scene resolve_scene_source(const std::string& scene, const std::string& model);

}  // namespace penumbra
