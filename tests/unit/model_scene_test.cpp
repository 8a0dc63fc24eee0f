// Models in scenes: placement (scale, rotation, translation), materials
// appended or overridden, the JSON model shape, and the framed scene that
// --model renders.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>

#include "model_files.hpp"
#include "penumbra/error.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"
#include "scene/scene_file.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::kTetrahedronHeight;
using testing::red_mtl;
using testing::tetrahedron_obj;
using testing::write_model_file;

TEST(ShapeScale, ScalesBeforeRotatingAndMoving) {
  Shape box;
  box.kind = ShapeKind::Box;
  box.size = glm::vec3(1.0f);
  box.scale = {2.0f, 1.0f, 0.5f};
  box.rotation_degrees = {0.0f, 90.0f, 0.0f};  // x -> -z
  box.position = {10.0f, 0.0f, 0.0f};
  TriangleMesh mesh;
  append_shape(mesh, box);
  const Bounds b = mesh.bounds();
  EXPECT_NEAR(b.min.x, 10.0f - 0.25f, 1e-5f);
  EXPECT_NEAR(b.max.x, 10.0f + 0.25f, 1e-5f);
  EXPECT_NEAR(b.min.z, -1.0f, 1e-5f);
  EXPECT_NEAR(b.max.z, 1.0f, 1e-5f);
  EXPECT_NEAR(b.max.y, 0.5f, 1e-5f);
}

// A sphere scaled into an ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the
// normal at p is along (x/a^2, y/b^2, z/c^2), not the scaled sphere normal.
TEST(ShapeScale, NormalsOfAnEllipsoidAreTheInverseTranspose) {
  Shape sphere;
  sphere.kind = ShapeKind::Sphere;
  sphere.radius = 1.0f;
  sphere.scale = {3.0f, 1.0f, 0.5f};
  TriangleMesh mesh;
  append_shape(mesh, sphere);
  for (const Vertex& v : mesh.vertices) {
    const glm::vec3 expected = glm::normalize(v.position / (sphere.scale * sphere.scale));
    EXPECT_NEAR(glm::dot(v.normal, expected), 1.0f, 1e-4f) << v.position.x << " " << v.position.y;
  }
}

TEST(ShapeScale, UnitScaleLeavesShapesAsBefore) {
  // The placement without a scale: translate * rotate, normals rotated.
  Shape torus;
  torus.kind = ShapeKind::Torus;
  torus.rotation_degrees = {60.0f, 20.0f, 5.0f};
  torus.position = {2.6f, 1.1f, 0.2f};
  TriangleMesh mesh;
  append_shape(mesh, torus);
  Shape origin = torus;
  origin.rotation_degrees = glm::vec3(0.0f);
  origin.position = glm::vec3(0.0f);
  TriangleMesh local;
  append_shape(local, origin);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), torus.position);
  m = glm::rotate(m, glm::radians(5.0f), {0, 0, 1});
  m = glm::rotate(m, glm::radians(20.0f), {0, 1, 0});
  m = glm::rotate(m, glm::radians(60.0f), {1, 0, 0});
  ASSERT_EQ(mesh.vertices.size(), local.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_EQ(mesh.vertices[i].position, glm::vec3(m * glm::vec4(local.vertices[i].position, 1)));
    // (The local normals were normalized once more: an ulp apart.)
    const glm::vec3 normal = glm::normalize(glm::mat3(m) * local.vertices[i].normal);
    EXPECT_LT(glm::length(mesh.vertices[i].normal - normal), 1e-6f);
  }
}

TEST(ModelShape, OwnMaterialsAreAppendedAndOverridesReplaceThem) {
  write_model_file("scene-red.mtl", red_mtl());
  const std::string path = write_model_file("scene-red.obj", tetrahedron_obj("scene-red.mtl"));
  Scene scene;
  scene.materials = {Material{"first", glm::vec3(0.5f), glm::vec3(0.0f), 8.0f}};
  Shape own, plain;
  attach_model(scene, own, path, /*own_materials=*/true);
  plain.material = 0;
  attach_model(scene, plain, path, /*own_materials=*/false);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(own.material, 1);
  EXPECT_NEAR(scene.materials[1].albedo.r, 0.8f, 1e-6f);
  scene.shapes = {own, plain};
  const TriangleMesh mesh = build_scene_mesh(scene);
  const std::size_t half = mesh.vertices.size() / 2;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_EQ(mesh.vertices[i].material, i < half ? 1u : 0u);
  }
}

TEST(ModelShape, SceneFileReadsModelsRelativeToItsFolder) {
  write_model_file("scene-dir/parts/tet.mtl", red_mtl());
  write_model_file("scene-dir/parts/tet.obj", tetrahedron_obj("tet.mtl"));
  const std::string json = R"({
    "materials": {"blue": {"albedo": [0.1, 0.2, 0.9]}},
    "lights": [{"type": "spot", "position": [0, 8, 0], "target": [0, 0, 0]}],
    "objects": [{"shape": "plane", "size": [10, 0, 10], "scale": [2, 1, 2]},
                {"shape": "model", "file": "parts/tet.obj", "scale": 2, "position": [1, 0, 0]},
                {"shape": "model", "file": "parts/tet.obj", "scale": [1, 3, 1],
                 "rotation": [0, 90, 0], "material": "blue"}]
  })";
  const std::string scene_path = write_model_file("scene-dir/scene.json", json);
  const Scene scene = load_scene_file(scene_path);
  ASSERT_EQ(scene.shapes.size(), 3u);
  EXPECT_EQ(scene.shapes[0].scale, glm::vec3(2.0f, 1.0f, 2.0f));
  const Shape& own = scene.shapes[1];
  EXPECT_EQ(own.kind, ShapeKind::Model);
  EXPECT_EQ(own.scale, glm::vec3(2.0f));
  EXPECT_TRUE(own.own_materials);
  EXPECT_NEAR(scene.materials.at(static_cast<std::size_t>(own.material)).albedo.r, 0.8f, 1e-6f);
  const Shape& blue = scene.shapes[2];
  EXPECT_FALSE(blue.own_materials);
  EXPECT_EQ(scene.materials.at(static_cast<std::size_t>(blue.material)).name, "blue");

  TriangleMesh mesh;
  append_shape(mesh, blue);
  EXPECT_NEAR(mesh.bounds().max.y, 3.0f * kTetrahedronHeight, 1e-5f);
  TriangleMesh moved;
  append_shape(moved, own);
  EXPECT_NEAR(moved.bounds().max.x, 1.0f + 2.0f * 0.6f, 1e-5f);
}

TEST(ModelShape, SceneFileErrorsNameTheKeyAndTheModel) {
  write_model_file("scene-errors/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  struct Case {
    const char* object;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"shape": "model"})", "/objects/0/file: missing"},
      {R"({"shape": "model", "file": "nothere.obj"})", "/objects/0/file: "},
      {R"({"shape": "model", "file": "bad.obj"})",
       "bad.obj: line 4: position index 99 is out of range"},
      {R"({"shape": "model", "file": 3})", "/objects/0/file: expected a string"},
      {R"({"shape": "box", "scale": 0})", "/objects/0/scale: must be between"},
      {R"({"shape": "box", "scale": [1, -1, 1]})", "/objects/0/scale/1: must be between"},
      {R"({"shape": "box", "scale": "big"})", "/objects/0/scale: expected a number"},
      {R"({"shape": "teapot"})", "/objects/0/shape: unknown shape"},
  };
  for (const Case& c : cases) {
    const std::string json =
        std::string(R"({"lights": [{"type": "spot"}], "objects": [)") + c.object + "]}";
    const std::string path = write_model_file("scene-errors/scene.json", json);
    try {
      load_scene_file(path);
      ADD_FAILURE() << "accepted: " << c.object;
    } catch (const RuntimeError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(c.expected), std::string::npos)
          << "message: " << message << "\nexpected: " << c.expected;
    }
  }
  // The missing model is named with the scene's folder in front.
  try {
    load_scene_file(write_model_file(
        "scene-errors/scene.json",
        R"({"lights": [{}], "objects": [{"shape": "model", "file": "nothere.obj"}]})"));
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("scene-errors/nothere.obj: no such file"),
              std::string::npos)
        << e.what();
  }
}

// The model stands on the ground, kFramedModelSize across, and the camera
// sees all of it at 16:9 and at 1:1.
TEST(FramedModelScene, StandsOnTheGroundInView) {
  // Lying on its side and far from the origin in the file.
  write_model_file("framed.mtl", red_mtl());
  std::string obj = "mtllib framed.mtl\nv 100 5 5\nv 100 5 9\nv 100 7 5\nv 104 5 5\nusemtl red\n";
  obj += "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  const Scene scene = framed_model_scene(write_model_file("framed.obj", obj));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::Spot);
  EXPECT_EQ(scene.lights[1].type, LightType::Directional);
  ASSERT_EQ(scene.shapes.size(), 2u);
  EXPECT_EQ(scene.shapes[0].kind, ShapeKind::Plane);
  const Shape& model = scene.shapes[1];
  ASSERT_EQ(model.kind, ShapeKind::Model);
  EXPECT_NEAR(scene.materials.at(static_cast<std::size_t>(model.material)).albedo.r, 0.8f, 1e-6f);

  TriangleMesh mesh;
  append_shape(mesh, model);
  const Bounds b = mesh.bounds();
  EXPECT_NEAR(b.min.y, 0.0f, 1e-5f);
  const glm::vec3 extent = b.max - b.min;
  EXPECT_NEAR(std::max({extent.x, extent.y, extent.z}), kFramedModelSize, 1e-5f);
  EXPECT_NEAR(b.center().x, 0.0f, 1e-5f);
  EXPECT_NEAR(b.center().z, 0.0f, 1e-5f);

  const glm::mat4 view = glm::lookAt(scene.camera.position, scene.camera.target, scene.camera.up);
  for (const float aspect : {16.0f / 9.0f, 1.0f}) {
    const glm::mat4 projection =
        glm::perspective(glm::radians(scene.camera.fov_y_degrees), aspect, 0.01f, 100.0f);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p{corner & 1 ? b.max.x : b.min.x, corner & 2 ? b.max.y : b.min.y,
                        corner & 4 ? b.max.z : b.min.z};
      const glm::vec4 clip = projection * view * glm::vec4(p, 1.0f);
      ASSERT_GT(clip.w, 0.0f);
      EXPECT_LT(std::abs(clip.x / clip.w), 1.0f) << "corner " << corner << ", aspect " << aspect;
      EXPECT_LT(std::abs(clip.y / clip.w), 1.0f) << "corner " << corner << ", aspect " << aspect;
    }
  }
  // As documented: the bounding sphere fills 80% of the image's height
  // (in angle), seen from 40 degrees above the ground.
  const glm::vec3 centre = b.center();
  const float radius = 0.5f * glm::length(extent);
  const glm::vec3 to_camera = scene.camera.position - centre;
  EXPECT_NEAR(
      2.0f * std::asin(radius / glm::length(to_camera)) / glm::radians(scene.camera.fov_y_degrees),
      0.8f, 0.01f);
  EXPECT_NEAR(glm::degrees(std::asin(glm::normalize(to_camera).y)), 40.0f, 0.01f);
  // The spot light reaches the model.
  const Light& spot = scene.lights[0];
  const glm::vec3 to_model = glm::normalize(b.center() - spot.position);
  EXPECT_GT(glm::dot(to_model, spot.direction), std::cos(glm::radians(spot.inner_cone_degrees)));
}

// As documented (docs/scenes.md): the bounding sphere fills 80% of the
// image's height, whatever the model's proportions; the model itself fills
// less (its bounding box's corners are on the sphere at most).
TEST(FramedModelScene, BoundingSphereFillsFourFifthsOfTheHeight) {
  for (const glm::vec3 extent :
       {glm::vec3(2.0f, 1.9f, 1.5f), glm::vec3(1, 2, 1), glm::vec3(2, 1, 1)}) {
    Bounds b;
    b.extend(-0.5f * extent + glm::vec3(0, 0.5f * extent.y, 0));
    b.extend(0.5f * extent + glm::vec3(0, 0.5f * extent.y, 0));
    const Camera camera = framing_camera(b);
    const glm::mat4 clip =
        glm::perspective(glm::radians(camera.fov_y_degrees), 1.0f, 0.01f, 100.0f) *
        glm::lookAt(camera.position, camera.target, camera.up);
    const float radius = 0.5f * glm::length(extent);
    float low = 1.0f, high = -1.0f;
    for (int i = 0; i < 180; ++i) {
      for (int j = 0; j <= 90; ++j) {
        const float theta = glm::radians(2.0f * static_cast<float>(i));
        const float phi = glm::radians(2.0f * static_cast<float>(j));
        const glm::vec3 p =
            b.center() + radius * glm::vec3(std::sin(phi) * std::cos(theta), std::cos(phi),
                                            std::sin(phi) * std::sin(theta));
        const glm::vec4 c = clip * glm::vec4(p, 1.0f);
        low = std::min(low, c.y / c.w);
        high = std::max(high, c.y / c.w);
      }
    }
    std::printf("extent (%.1f, %.1f, %.1f): the sphere spans %.3f of the height\n", extent.x,
                extent.y, extent.z, 0.5f * (high - low));
    // The sphere's angular diameter is exactly 80% of the field of view
    // (StandsOnTheGroundInView); off the view's axis (the aim is below its
    // centre) its projection on the image spans a little less.
    EXPECT_NEAR(0.5f * (high - low), 0.8f, 0.025f);
  }
}

TEST(FramedModelScene, BadModelsAreErrorsNamingTheFile) {
  const std::string flat = write_model_file("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  try {
    framed_model_scene(flat);
    ADD_FAILURE() << "a model at one point was framed";
  } catch (const RuntimeError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(flat + ": ", 0), 0u) << e.what();
  }
  EXPECT_THROW(framed_model_scene(flat + ".missing"), RuntimeError);
}

}  // namespace
}  // namespace penumbra
