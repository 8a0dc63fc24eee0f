#include "app/scene_source.hpp"

#include "app/option_style.hpp"
#include "penumbra/error.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {

void add_scene_source_options(CLI::App& command, std::string& scene, std::string& model,
                              int& camera_index) {
  CLI::Option* scene_option =
      command
          .add_option("--scene", scene,
                      "built-in scene (default, spot), a .json scene file, or a glTF scene "
                      "(.gltf, .glb) at its own scale with its camera and lights")
          ->capture_default_str()
          ->type_name("NAME|FILE");
  in_group(suggest_names(scene_option, builtin_scene_names()), OptionGroup::SceneAndCamera);
  CLI::Option* model_option =
      command
          .add_option("--model", model,
                      "a model file (OBJ, PLY, glTF/GLB, STL, OFF, or another format assimp "
                      "reads) scaled to 2 units, standing on a ground plane, framed by the camera, "
                      "lit by a spot and a directional light; instead of --scene")
          ->type_name("FILE")
          ->excludes(scene_option);
  in_group(model_option, OptionGroup::SceneAndCamera);
  CLI::Option* camera_option =
      command
          .add_option("--camera-index", camera_index,
                      "which of a glTF scene's cameras to look through (default: its first)")
          ->type_name("N")
          ->transform(index_number());
  in_group(camera_option, OptionGroup::SceneAndCamera);
}

Scene resolve_scene_source(const std::string& scene, const std::string& model, int camera_index) {
  if (camera_index >= 0 && (!model.empty() || !is_gltf_path(scene))) {
    throw UsageError("--camera-index needs a glTF scene (--scene FILE.gltf or FILE.glb)");
  }
  if (!model.empty()) return framed_model_scene(model);
  return resolve_scene(scene, camera_index);
}

}  // namespace penumbra
