#pragma once
// Where a command's scene comes from: `--scene` (a built-in name, a JSON
// scene file, or a glTF scene with `--camera-index` and `--ground`) or `--model` (a model
// file framed on a ground plane by framed_model_scene). Every command that
// renders a scene takes them.
#include <CLI/CLI.hpp>
#include <string>

#include "scene/scene.hpp"

namespace penumbra {

// Registers --scene, --model, --camera-index and --ground; giving both
// --scene and --model is a usage error.
void add_scene_source_options(CLI::App& command, std::string& scene, std::string& model,
                              int& camera_index, bool& ground);

// The scene they name: the model's framed scene when `model` is set.
// Throws UsageError for an unknown scene name, a camera index the scene
// lacks, or a camera index or ground given for a scene that is not glTF;
// RuntimeError for a file that cannot be read or parsed.
Scene resolve_scene_source(const std::string& scene, const std::string& model, int camera_index,
                           bool ground);

}  // namespace penumbra
