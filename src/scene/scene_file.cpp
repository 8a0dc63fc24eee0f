#include "scene/scene_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/display_name.hpp"
#include "io/bounded_read.hpp"
#include "penumbra/error.hpp"
#include "penumbra/settings.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/model.hpp"
#include "scene/scene_checks.hpp"

namespace penumbra {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// Reads values from one JSON object, tracking the key path for messages
// and rejecting keys nobody asked for.
class Reader {
 public:
  Reader(const json& value, std::string path, const std::string& origin)
      : value_(value), path_(std::move(path)), origin_(origin) {
    if (!value_.is_object()) fail(path_, "expected an object");
  }

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    // The file's name escaped (core/display_name.hpp): a newline in it
    // must not split the one-line error.
    throw RuntimeError(escape_control(origin_) + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  [[nodiscard]] std::string child(const std::string& key) const { return path_ + "/" + key; }
  bool has(const std::string& key) {
    known_.insert(key);
    return value_.contains(key);
  }
  const json& at(const std::string& key) {
    known_.insert(key);
    return value_.at(key);
  }

  float number(const std::string& key, float fallback, float min, float max) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_number()) fail(child(key), "expected a number");
    double d = v.get<double>();
    if (!std::isfinite(d) || d < min || d > max) {
      std::ostringstream msg;
      msg << "must be between " << min << " and " << max << " (got " << v.dump() << ")";
      fail(child(key), msg.str());
    }
    return static_cast<float>(d);
  }

  glm::vec3 vec3(const std::string& key, glm::vec3 fallback, float min = -1e6f, float max = 1e6f) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_array() || v.size() != 3) fail(child(key), "expected an array of 3 numbers");
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
      const json& e = v[static_cast<std::size_t>(i)];
      if (!e.is_number()) fail(child(key) + "/" + std::to_string(i), "expected a number");
      double d = e.get<double>();
      if (!std::isfinite(d) || d < min || d > max) {
        std::ostringstream msg;
        msg << "must be between " << min << " and " << max;
        fail(child(key) + "/" + std::to_string(i), msg.str());
      }
      out[i] = static_cast<float>(d);
    }
    return out;
  }

  std::string string(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_string()) fail(child(key), "expected a string");
    return v.get<std::string>();
  }

  // Call after reading: any key not asked for is an error.
  void reject_unknown_keys() const {
    for (auto it = value_.begin(); it != value_.end(); ++it) {
      if (!known_.count(it.key())) fail(child(it.key()), "unknown key");
    }
  }

 private:
  const json& value_;
  std::string path_;
  const std::string& origin_;
  std::set<std::string> known_;
};

constexpr float kMaxExtent = 1e5f;

Camera read_camera(Reader r, Camera camera) {
  camera.position = r.vec3("position", camera.position);
  camera.target = r.vec3("target", camera.target);
  camera.up = r.vec3("up", camera.up);
  camera.fov_y_degrees = r.number("fov", camera.fov_y_degrees, 1.0f, 170.0f);
  switch (camera_defect(camera)) {
    case CameraDefect::TargetAtPosition:
      r.fail(r.child("target"), "must differ from the position");
    case CameraDefect::UpAlongView:
      r.fail(r.child("up"), "must not be parallel to the viewing direction");
    case CameraDefect::None:
      break;
  }
  r.reject_unknown_keys();
  return camera;
}

Material read_material(Reader r, const std::string& name) {
  Material m;
  m.name = name;
  m.albedo = r.vec3("albedo", m.albedo, 0.0f, 1.0f);
  m.specular = r.vec3("specular", m.specular, 0.0f, 1.0f);
  m.shininess = r.number("shininess", m.shininess, 1.0f, 10000.0f);
  r.reject_unknown_keys();
  return m;
}

Light read_light(Reader r) {
  Light l;
  std::string type = r.string("type", "spot");
  if (type == "spot") {
    l.type = LightType::Spot;
  } else if (type == "directional") {
    l.type = LightType::Directional;
  } else if (type == "point") {
    l.type = LightType::Point;
  } else {
    r.fail(r.child("type"),
           "must be \"spot\", \"directional\" or \"point\" (got \"" + type + "\")");
  }
  if (l.type != LightType::Directional) l.position = r.vec3("position", l.position);
  if (r.has("target") && r.has("direction"))
    r.fail(r.child("target"), "give either \"target\" or \"direction\", not both");
  if (r.has("target")) {
    if (l.type != LightType::Spot) r.fail(r.child("target"), "only spot lights have a target");
    glm::vec3 target = r.vec3("target", {});
    if (!is_usable_direction(target - l.position))
      r.fail(r.child("target"), "must differ from the position");
    l.direction = glm::normalize(target - l.position);
  } else if (l.type != LightType::Point) {  // a point light shines every way
    glm::vec3 d = r.vec3("direction", l.direction);
    if (!is_usable_direction(d)) r.fail(r.child("direction"), "must not be zero");
    l.direction = glm::normalize(d);
  }
  l.color = r.vec3("color", l.color, 0.0f, 1e3f);
  l.intensity = r.number("intensity", l.intensity, 0.0f, 1e6f);
  if (l.type == LightType::Spot) {
    l.cone_degrees = r.number("cone", l.cone_degrees, 1.0f, 80.0f);
    l.inner_cone_degrees = r.number("inner_cone", std::min(l.inner_cone_degrees, l.cone_degrees),
                                    0.0f, l.cone_degrees);
  }
  // The source's size (kSourceSizeParams: "light_size" for spot and point
  // lights, "sun_angle" for directional ones), each light its own.
  for (const SourceSizeParam& p : kSourceSizeParams) {
    const bool sun = p.light_field == &Light::sun_angle;
    std::string key(p.name);
    std::replace(key.begin(), key.end(), '-', '_');
    if (sun != (l.type == LightType::Directional)) {
      if (r.has(key)) {
        r.fail(r.child(key), sun ? "only directional lights have a sun_angle (spot and point "
                                   "lights: light_size)"
                                 : "directional lights have a sun_angle, not a light_size");
      }
      continue;
    }
    l.*(p.light_field) = r.number(key, l.*(p.light_field), p.min, p.max);
  }
  r.reject_unknown_keys();
  return l;
}

// "scale": one number for every axis, or [x, y, z].
glm::vec3 read_scale(Reader& r) {
  constexpr float kMin = 1e-6f, kMax = 1e6f;
  if (r.has("scale") && r.at("scale").is_array()) return r.vec3("scale", {}, kMin, kMax);
  return glm::vec3(r.number("scale", 1.0f, kMin, kMax));
}

// Reads one object into the scene; a model is loaded from `base_dir`.
void read_shape(Reader r, const std::map<std::string, int>& materials, const fs::path& base_dir,
                Scene& scene) {
  Shape s;
  std::string shape = r.string("shape", "");
  static const std::map<std::string, ShapeKind> kinds = {
      {"plane", ShapeKind::Plane},       {"box", ShapeKind::Box},     {"sphere", ShapeKind::Sphere},
      {"cylinder", ShapeKind::Cylinder}, {"torus", ShapeKind::Torus}, {"model", ShapeKind::Model}};
  auto kind = kinds.find(shape);
  if (kind == kinds.end()) {
    r.fail(r.child("shape"), shape.empty()
                                 ? "missing (plane, box, sphere, cylinder, torus or model)"
                                 : "unknown shape \"" + shape + "\"");
  }
  s.kind = kind->second;
  switch (s.kind) {
    case ShapeKind::Plane: {
      glm::vec3 size = r.vec3("size", {10.0f, 0.0f, 10.0f}, 0.0f, kMaxExtent);
      if (size.x <= 0.0f || size.z <= 0.0f) r.fail(r.child("size"), "x and z must be > 0");
      s.size = size;
      break;
    }
    case ShapeKind::Box:
      s.size = r.vec3("size", s.size, 1e-4f, kMaxExtent);
      break;
    case ShapeKind::Sphere:
      s.radius = r.number("radius", s.radius, 1e-4f, kMaxExtent);
      break;
    case ShapeKind::Cylinder:
      s.radius = r.number("radius", s.radius, 1e-4f, kMaxExtent);
      s.height = r.number("height", s.height, 1e-4f, kMaxExtent);
      break;
    case ShapeKind::Torus:
      s.radius = r.number("radius", s.radius, 1e-4f, kMaxExtent);
      s.tube = r.number("tube", s.tube, 1e-4f, s.radius);
      break;
    case ShapeKind::Model: {
      const std::string file = r.string("file", "");
      if (file.empty()) r.fail(r.child("file"), "missing (the model file, relative to the scene)");
      s.file = (base_dir / file).lexically_normal().string();
      break;
    }
  }
  s.scale = read_scale(r);
  s.position = r.vec3("position", s.position, -kMaxExtent, kMaxExtent);
  s.rotation_degrees = r.vec3("rotation", s.rotation_degrees, -3600.0f, 3600.0f);
  std::string material = r.string("material", "");
  if (!material.empty()) {
    auto it = materials.find(material);
    if (it == materials.end()) r.fail(r.child("material"), "no material \"" + material + "\"");
    s.material = it->second;
  }
  r.reject_unknown_keys();
  if (s.kind == ShapeKind::Model) {
    // Without "material" the model keeps the colours its file gives.
    try {
      attach_model(scene, s, s.file, material.empty());
    } catch (const RuntimeError& e) {
      r.fail(r.child("file"), e.what());
    }
  }
  scene.shapes.push_back(std::move(s));
}

}  // namespace

Scene parse_scene_json(const std::string& text, const std::string& origin) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for a number beyond double's range.
    throw RuntimeError(origin + ": not valid JSON: " + e.what());
  }
  Scene scene;
  scene.name = origin;
  Reader r(root, "", origin);

  // Material 0 is the default for objects that name none.
  scene.materials.push_back(Material{"default", glm::vec3(0.8f), glm::vec3(0.04f), 32.0f});
  std::map<std::string, int> material_index;
  if (r.has("materials")) {
    const json& materials = r.at("materials");
    if (!materials.is_object()) r.fail("/materials", "expected an object of named materials");
    for (auto it = materials.begin(); it != materials.end(); ++it) {
      material_index[it.key()] = static_cast<int>(scene.materials.size());
      scene.materials.push_back(
          read_material(Reader(it.value(), "/materials/" + it.key(), origin), it.key()));
    }
  }
  if (r.has("camera"))
    scene.camera = read_camera(Reader(r.at("camera"), "/camera", origin), scene.camera);

  auto read_array = [&](const std::string& key) -> const json& {
    if (!r.has(key)) r.fail("/" + key, "missing (at least one entry is needed)");
    const json& a = r.at(key);
    if (!a.is_array() || a.empty()) r.fail("/" + key, "expected a non-empty array");
    return a;
  };
  const json& lights = read_array("lights");
  if (lights.size() > 4) r.fail("/lights", "at most 4 lights are supported");
  for (std::size_t i = 0; i < lights.size(); ++i) {
    scene.lights.push_back(read_light(Reader(lights[i], "/lights/" + std::to_string(i), origin)));
  }
  const json& objects = read_array("objects");
  const fs::path base_dir = fs::path(origin).parent_path();
  for (std::size_t i = 0; i < objects.size(); ++i) {
    read_shape(Reader(objects[i], "/objects/" + std::to_string(i), origin), material_index,
               base_dir, scene);
  }
  r.reject_unknown_keys();
  return scene;
}

Scene load_scene_file(const std::string& path) {
  return parse_scene_json(read_bounded_file(path, kMaxSceneFileBytes, "scene file"), path);
}

Scene resolve_scene(const std::string& name_or_path, int camera_index) {
  if (auto scene = builtin_scene(name_or_path)) return *scene;
  const bool looks_like_file =
      name_or_path.find('/') != std::string::npos || name_or_path.find('.') != std::string::npos;
  if (!looks_like_file) {
    std::string names;
    for (const std::string& n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("unknown scene '" + name_or_path + "' (built-in scenes: " + names +
                     "; or a path to a .json, .gltf or .glb scene file)");
  }
  if (is_gltf_path(name_or_path)) return gltf_scene(name_or_path, camera_index);
  return load_scene_file(name_or_path);
}

}  // namespace penumbra
