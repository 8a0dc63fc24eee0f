#include "scene/builtin_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <sstream>

#include "penumbra/error.hpp"
#include "scene/model.hpp"

namespace penumbra {

namespace {

std::vector<Material> standard_materials() {
  return {
      {"ground", {0.70f, 0.70f, 0.68f}, {0.02f, 0.02f, 0.02f}, 8.0f},
      {"red", {0.70f, 0.12f, 0.10f}, {0.25f, 0.25f, 0.25f}, 48.0f},
      {"blue", {0.12f, 0.25f, 0.70f}, {0.30f, 0.30f, 0.30f}, 96.0f},
      {"gold", {0.75f, 0.55f, 0.15f}, {0.40f, 0.35f, 0.20f}, 64.0f},
      {"white", {0.80f, 0.80f, 0.80f}, {0.10f, 0.10f, 0.10f}, 24.0f},
      {"green", {0.15f, 0.55f, 0.20f}, {0.20f, 0.20f, 0.20f}, 32.0f},
  };
}

Shape make(ShapeKind kind, glm::vec3 position, int material) {
  Shape s;
  s.kind = kind;
  s.position = position;
  s.material = material;
  return s;
}

// A dim, bluish directional light from the upper left: the sky's fill
// beside a scene's key spot light.
Light sky_light() {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.7f, -1.0f, -0.25f));
  sun.color = {0.75f, 0.82f, 1.0f};
  sun.intensity = 0.35f;
  return sun;
}

// A ground plane with casters at several heights, so that contact shadows
// and penumbrae of different widths appear side by side.
Scene default_scene() {
  Scene scene;
  scene.name = "default";
  scene.materials = standard_materials();

  Shape ground = make(ShapeKind::Plane, {0, 0, 0}, 0);
  ground.size = {24.0f, 0.0f, 24.0f};
  scene.shapes.push_back(ground);

  Shape box = make(ShapeKind::Box, {-2.6f, 0.75f, 0.6f}, 1);  // on the ground: contact shadow
  box.size = {1.5f, 1.5f, 1.5f};
  box.rotation_degrees = {0.0f, 25.0f, 0.0f};
  scene.shapes.push_back(box);

  Shape sphere = make(ShapeKind::Sphere, {0.2f, 1.6f, 1.4f}, 2);  // floating low
  sphere.radius = 0.7f;
  scene.shapes.push_back(sphere);

  Shape torus = make(ShapeKind::Torus, {2.6f, 1.1f, 0.2f}, 3);  // tilted, middle height
  torus.radius = 0.75f;
  torus.tube = 0.22f;
  torus.rotation_degrees = {60.0f, 20.0f, 0.0f};
  scene.shapes.push_back(torus);

  Shape pole = make(ShapeKind::Cylinder, {-0.6f, 1.5f, -1.6f}, 4);  // thin, standing
  pole.radius = 0.06f;
  pole.height = 3.0f;
  scene.shapes.push_back(pole);

  Shape slab = make(ShapeKind::Box, {1.0f, 3.8f, 2.0f}, 5);  // flat, high: wide penumbra
  slab.size = {1.8f, 0.12f, 1.2f};
  slab.rotation_degrees = {0.0f, -15.0f, 0.0f};
  scene.shapes.push_back(slab);

  scene.camera.position = {0.0f, 6.5f, 10.5f};
  scene.camera.target = {0.0f, 0.9f, 0.0f};
  scene.camera.fov_y_degrees = 45.0f;

  Light spot;
  spot.type = LightType::Spot;
  spot.position = {3.5f, 9.0f, 4.5f};
  spot.direction = glm::normalize(glm::vec3(0.0f, 0.6f, 0.0f) - spot.position);
  spot.color = {1.0f, 0.95f, 0.85f};
  spot.intensity = 90.0f;
  spot.cone_degrees = 38.0f;
  spot.inner_cone_degrees = 30.0f;
  scene.lights.push_back(spot);

  scene.lights.push_back(sky_light());
  return scene;
}

// One spot light shining down at a few objects on a floor, the set-up of
// the seed assignment's "Spot Light" scene.
Scene spot_scene() {
  Scene scene;
  scene.name = "spot";
  scene.materials = standard_materials();

  Shape floor = make(ShapeKind::Plane, {0, 0, 0}, 0);
  floor.size = {16.0f, 0.0f, 16.0f};
  scene.shapes.push_back(floor);

  Shape sphere = make(ShapeKind::Sphere, {-1.2f, 1.0f, 0.0f}, 2);
  sphere.radius = 1.0f;
  scene.shapes.push_back(sphere);

  Shape box = make(ShapeKind::Box, {1.4f, 0.6f, 0.8f}, 1);
  box.size = {1.2f, 1.2f, 1.2f};
  box.rotation_degrees = {0.0f, 40.0f, 0.0f};
  scene.shapes.push_back(box);

  Shape pillar = make(ShapeKind::Cylinder, {0.6f, 1.25f, -1.6f}, 4);
  pillar.radius = 0.3f;
  pillar.height = 2.5f;
  scene.shapes.push_back(pillar);

  scene.camera.position = {0.0f, 5.0f, 8.0f};
  scene.camera.target = {0.0f, 0.6f, 0.0f};
  scene.camera.fov_y_degrees = 45.0f;

  Light spot;
  spot.type = LightType::Spot;
  spot.position = {-1.5f, 7.0f, 3.0f};
  spot.direction = glm::normalize(glm::vec3(0.3f, 0.0f, -0.2f) - spot.position);
  spot.color = {1.0f, 1.0f, 1.0f};
  spot.intensity = 60.0f;
  spot.cone_degrees = 35.0f;
  spot.inner_cone_degrees = 27.0f;
  scene.lights.push_back(spot);
  return scene;
}

}  // namespace

Scene framed_model_scene(const std::string& path) {
  Scene scene;
  scene.name = path;
  scene.materials = standard_materials();
  Shape model;
  attach_model(scene, model, path, /*own_materials=*/true);

  const Bounds& b = model.model->bounds;
  const glm::vec3 extent = b.max - b.min;
  const float largest = std::max({extent.x, extent.y, extent.z});
  // Bounds that pass leave the scale a normal float too (a GPU flushes
  // smaller ones to zero): largest < 3.4e37, so scale > 5.9e-38.
  check_frameable(path, b, "a framed view");
  if (largest <= 0.0f) {
    throw RuntimeError(path + ": the model has no extent (every vertex is at one point)");
  }
  const float scale = kFramedModelSize / largest;
  model.scale = glm::vec3(scale);
  // Centred over the origin, its lowest point on the ground.
  model.position = {-scale * b.center().x, -scale * b.min.y, -scale * b.center().z};
  const float radius = 0.5f * scale * glm::length(extent);  // of the bounding sphere
  scene.shapes.push_back(model);

  // Just wide enough that the camera below sees no edge of it: a
  // directional light's map covers all of it, so every extra metre of
  // ground costs shadow-map texels on the model.
  Shape ground = make(ShapeKind::Plane, {0, 0, 0}, 0);
  ground.size = {10.0f * radius, 0.0f, 10.0f * radius};
  scene.shapes.insert(scene.shapes.begin(), ground);

  Bounds placed;
  placed.extend(scale * b.min + model.position);
  placed.extend(scale * b.max + model.position);
  scene.camera = framing_camera(placed);
  scene.lights = framing_lights(placed);
  return scene;
}

namespace {

// Where framed_model_scene's camera and key light stand, as azimuths about
// the vertical axis (0: the front, +z; positive towards +x) and elevations
// above the horizon. The light is 105 degrees round from the camera: it
// still lights the faces the camera sees from the side (the model's front,
// 35 degrees off the camera's line of sight), and the shadow it throws
// falls beside the model and towards the camera, where the camera sees it,
// not behind the model.
constexpr float kCameraAzimuth = -35.0f, kCameraElevation = 40.0f;
constexpr float kKeyLightAzimuth = 70.0f, kKeyLightElevation = 45.0f;

glm::vec3 direction_at(float azimuth_degrees, float elevation_degrees) {
  const float a = glm::radians(azimuth_degrees), e = glm::radians(elevation_degrees);
  return {std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e)};
}

// Unit vector along the ground in which the key light's shadows fall.
glm::vec3 key_shadow_direction() {
  const glm::vec3 from_light = -direction_at(kKeyLightAzimuth, kKeyLightElevation);
  return glm::normalize(glm::vec3(from_light.x, 0.0f, from_light.z));
}

}  // namespace

void check_frameable(const std::string& path, const Bounds& bounds, const char* what) {
  const float size = glm::length(bounds.max - bounds.min);
  if (!std::isfinite(10.0f * size)) {
    const glm::vec3 reach = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
    std::ostringstream text;
    text << path << ": coordinates reach " << std::max({reach.x, reach.y, reach.z})
         << ", too large to make " << what << " for (a float's range ends at 3.4e+38)";
    throw RuntimeError(text.str());
  }
}

Camera framing_camera(const Bounds& bounds) {
  const glm::vec3 extent = bounds.max - bounds.min;
  const float height = extent.y;
  const float radius = 0.5f * glm::length(extent);  // of the bounding sphere
  const glm::vec3 base{bounds.center().x, bounds.min.y, bounds.center().z};
  // From the front left, 40 degrees above the horizon (so that the top
  // edge of a 16:9 image still meets the ground), the bounding sphere
  // filling 80% of the image's height: the model itself fills less of it
  // (its box's diagonal is the sphere's diameter), which leaves room for
  // its shadow. The aim is a little below the middle and a little towards
  // the key light's shadow, so that the ground and the shadow show.
  Camera camera;
  camera.fov_y_degrees = 40.0f;
  const float distance = radius / std::sin(glm::radians(0.5f * camera.fov_y_degrees)) / 0.8f;
  camera.position = bounds.center() + distance * direction_at(kCameraAzimuth, kCameraElevation);
  camera.target =
      base + glm::vec3(0.0f, 0.4f * height, 0.0f) + 0.15f * radius * key_shadow_direction();
  return camera;
}

std::vector<Light> framing_lights(const Bounds& bounds) {
  const glm::vec3 extent = bounds.max - bounds.min;
  const float height = extent.y;
  const float radius = 0.5f * glm::length(extent);
  const glm::vec3 base{bounds.center().x, bounds.min.y, bounds.center().z};
  // Up high, to the right of the camera and a little behind the model
  // (kKeyLightAzimuth), far enough for a narrow cone to hold the model and
  // its shadow; aimed between the two.
  Light spot;
  spot.type = LightType::Spot;
  const glm::vec3 aim =
      base + glm::vec3(0.0f, 0.25f * height, 0.0f) + 0.3f * radius * key_shadow_direction();
  spot.position = aim + 4.8f * radius * direction_at(kKeyLightAzimuth, kKeyLightElevation);
  spot.direction = glm::normalize(aim - spot.position);
  spot.color = {1.0f, 0.95f, 0.85f};
  // About the default scene's irradiance where the light meets the model.
  spot.intensity = 0.9f * glm::dot(spot.position - aim, spot.position - aim);
  spot.cone_degrees = 32.0f;
  spot.inner_cone_degrees = 24.0f;
  return {spot, sky_light()};
}

void add_ground(Scene& scene, const Bounds& bounds) {
  const glm::vec3 extent = bounds.max - bounds.min;
  const float radius = 0.5f * glm::length(extent);
  Shape ground = make(ShapeKind::Plane, {bounds.center().x, bounds.min.y, bounds.center().z},
                      static_cast<int>(scene.materials.size()));
  ground.size = {10.0f * radius, 0.0f, 10.0f * radius};
  scene.materials.push_back(standard_materials()[0]);
  scene.shapes.insert(scene.shapes.begin(), ground);
}

std::vector<std::string> builtin_scene_names() {
  return {"default", "spot"};
}

std::optional<Scene> builtin_scene(const std::string& name) {
  if (name == "default") return default_scene();
  if (name == "spot") return spot_scene();
  return std::nullopt;
}

}  // namespace penumbra
