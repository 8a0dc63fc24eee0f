#include "scene/gltf_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "penumbra/error.hpp"
#include "penumbra/shared/bindings.h"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_extensions.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"

namespace penumbra {

static_assert(kMaxSceneLights == MAX_LIGHTS);

namespace {

// The extensions of a file the model reader can read at all: one it
// cannot is left for load_model's own message.
GltfExtensions read_gltf_extensions_checked(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return {};
  try {
    return read_gltf_extensions(path);
  } catch (const RuntimeError&) {
    return {};
  }
}

}  // namespace

bool is_gltf_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

bool has_ground(const TriangleMesh& mesh, const Bounds& bounds) {
  if (bounds.empty()) return false;
  const glm::vec3 extent = bounds.max - bounds.min;
  const float band = bounds.min.y + 0.01f * std::max({extent.x, extent.y, extent.z});
  const double footprint = static_cast<double>(extent.x) * static_cast<double>(extent.z);
  double area = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
    if (std::max({a.y, b.y, c.y}) > band) continue;
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (!(length > 0.0f) || std::abs(n.y) < 0.95f * length) continue;
    area += 0.5 * static_cast<double>(length);
  }
  return footprint > 0.0 && area >= 0.25 * footprint;
}

Scene gltf_scene(const std::string& path, int camera_index, GltfSceneNotes& notes, bool ground) {
  // The checks load_model makes first (a missing file, a folder, a FIFO)
  // come before the extensions are read.
  const GltfExtensions extensions = read_gltf_extensions_checked(path);
  std::string unread;
  for (const std::string& e : extensions.required) {
    if (!is_supported_gltf_extension(e)) {
      throw RuntimeError(path + ": requires the glTF extension " + e +
                         ", which penumbra does not read");
    }
  }
  for (const std::string& e : extensions.used) {
    if (!is_supported_gltf_extension(e)) unread += (unread.empty() ? "" : ", ") + e;
  }
  if (!unread.empty()) {
    notes.warnings.push_back(path +
                             ": ignoring the glTF extensions it uses that penumbra does not "
                             "read: " +
                             unread);
  }
  Scene scene;
  scene.name = path;
  Shape shape;
  attach_model(scene, shape, path, /*own_materials=*/true);
  const Model& model = *shape.model;
  scene.shapes.push_back(shape);

  if (camera_index >= static_cast<int>(model.cameras.size())) {
    throw UsageError("--camera-index " + std::to_string(camera_index) + ": " + path + " has " +
                     std::to_string(model.cameras.size()) + " camera" +
                     (model.cameras.size() == 1 ? "" : "s"));
  }
  if (camera_index < 0 && !model.cameras.empty()) camera_index = 0;
  if (camera_index >= 0) {
    const ModelCamera& camera = model.cameras[static_cast<std::size_t>(camera_index)];
    if (camera.orthographic) {
      throw UsageError(path + ": camera " + std::to_string(camera_index) + " ('" + camera.name +
                       "') is orthographic; penumbra draws perspective cameras only");
    }
    scene.camera = camera.camera;
  } else {
    if (model.bounds.empty()) throw RuntimeError(path + ": the file holds no triangles");
    check_frameable(path, model.bounds, "a camera");
    scene.camera = framing_camera(model.bounds);
    notes.assumptions.push_back(path +
                                " has no camera: looking at it from the front left, 40 "
                                "degrees up, its bounding sphere filling 80% of the image "
                                "height");
  }

  if (model.lights.empty()) {
    check_frameable(path, model.bounds, "lights");
    scene.lights = framing_lights(model.bounds);
    notes.assumptions.push_back(path +
                                " has no lights: lit by a spot light from the right and a "
                                "little behind, and a dim directional light");
  } else {
    // The dropped lights named up to a few, then counted: a file with
    // thousands of lights still gets one short warning line.
    constexpr std::size_t kNamed = 3;
    std::string dropped;
    std::size_t dropped_count = 0;
    for (std::size_t i = 0; i < model.lights.size(); ++i) {
      if (static_cast<int>(i) < kMaxSceneLights) {
        scene.lights.push_back(model.lights[i].light);
      } else if (dropped_count++ < kNamed) {
        dropped += (dropped.empty() ? "'" : ", '") + model.lights[i].name + "'";
      }
    }
    if (dropped_count > kNamed) {
      dropped += " and " + std::to_string(dropped_count - kNamed) + " more";
    }
    if (!dropped.empty()) {
      notes.warnings.push_back(path + ": penumbra draws at most " +
                               std::to_string(kMaxSceneLights) + " lights; dropped " +
                               std::to_string(dropped_count) + ": " + dropped);
    }
  }

  if (!has_ground(model.mesh, model.bounds)) {
    if (ground) {
      check_frameable(path, model.bounds, "a ground");
      add_ground(scene, model.bounds);
      notes.assumptions.push_back(path + " has no ground: added a grey plane under it (--ground)");
    } else {
      notes.assumptions.push_back(path + " has no ground: none added (--ground on adds one)");
    }
  }
  return scene;
}

Scene gltf_scene(const std::string& path, int camera_index, bool ground) {
  GltfSceneNotes notes;
  Scene scene = gltf_scene(path, camera_index, notes, ground);
  for (const std::string& w : notes.warnings) {
    std::fprintf(stderr, "penumbra: warning: %s\n", w.c_str());
  }
  for (const std::string& a : notes.assumptions) {
    std::fprintf(stderr, "penumbra: note: %s\n", a.c_str());
  }
  return scene;
}

}  // namespace penumbra
