// glTF files as scenes: their cameras, KHR_lights_punctual lights (with
// the spec's units), textures and what happens when parts are missing or
// broken.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/gtc/constants.hpp>

#include "gltf_files.hpp"
#include "model_files.hpp"
#include "penumbra/error.hpp"
#include "reference/caster_cutouts.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/gltf_lights.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"
#include "scene/texture.hpp"

namespace penumbra {
namespace {

using testing::GltfSpec;

GltfSpec ground_quad(float half = 2.0f) {
  GltfSpec spec;
  spec.quads.push_back(
      {{{-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half}}, 0});
  spec.materials.push_back({});
  return spec;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// The scene keeps the file's scale and adds no ground; camera and spot
// light come from their nodes.
TEST(GltfScene, CameraAndSpotLightComeFromTheFile) {
  GltfSpec spec = ground_quad(3.0f);
  spec.cameras.push_back({.position = {-6, 2, 1},
                          .target = {0, 0, 1},
                          .yfov = 0.7f,
                          .znear = 0.25f,
                          .zfar = 40.0f,
                          .aspect_ratio = 1.5f});
  spec.lights.push_back({.name = "red spot",
                         .type = "spot",
                         .color = {1, 0, 0},
                         .intensity = 80.0f,
                         .inner_cone = 0.2f,
                         .outer_cone = 0.5f,
                         .position = {0, 6, 0},
                         .direction = {0, -1, 0}});
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(testing::write_gltf("camera-spot.gltf", spec), -1, notes);
  EXPECT_TRUE(notes.warnings.empty());
  ASSERT_EQ(scene.shapes.size(), 1u) << "no ground plane added";
  EXPECT_EQ(scene.shapes[0].scale, glm::vec3(1.0f)) << "not rescaled";
  const Bounds b = build_scene_mesh(scene).bounds();
  expect_near(b.min, {-3, 0, -3}, 1e-6f);
  expect_near(b.max, {3, 0, 3}, 1e-6f);

  expect_near(scene.camera.position, {-6, 2, 1}, 1e-5f);
  expect_near(glm::normalize(scene.camera.target - scene.camera.position),
              glm::normalize(glm::vec3(6, -2, 0)), 1e-5f);
  EXPECT_NEAR(scene.camera.fov_y_degrees, glm::degrees(0.7f), 1e-3f) << "yfov, not x fov";
  EXPECT_FLOAT_EQ(scene.camera.near_plane, 0.25f);
  EXPECT_FLOAT_EQ(scene.camera.far_plane, 40.0f);

  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& l = scene.lights[0];
  EXPECT_EQ(l.type, LightType::Spot);
  expect_near(l.position, {0, 6, 0}, 1e-5f);
  expect_near(l.direction, {0, -1, 0}, 1e-5f);
  expect_near(l.color * l.intensity, {80, 0, 0}, 1e-3f);
  EXPECT_NEAR(l.cone_degrees, glm::degrees(0.5f), 1e-3f);
  EXPECT_NEAR(l.inner_cone_degrees, glm::degrees(0.2f), 1e-3f);
}

TEST(GltfScene, CameraIndexPicksAnotherAndOutOfRangeIsAUsageError) {
  GltfSpec spec = ground_quad();
  spec.cameras.push_back({.position = {0, 5, 5}, .target = {0, 0, 0}});
  spec.cameras.push_back({.position = {5, 1, 0}, .target = {0, 0, 0}, .yfov = 1.0f});
  const std::string path = testing::write_gltf("two-cameras.gltf", spec);
  GltfSceneNotes notes;
  EXPECT_NEAR(gltf_scene(path, -1, notes).camera.position.z, 5.0f, 1e-5f) << "the first";
  const Scene second = gltf_scene(path, 1, notes);
  expect_near(second.camera.position, {5, 1, 0}, 1e-5f);
  EXPECT_NEAR(second.camera.fov_y_degrees, glm::degrees(1.0f), 1e-3f);
  EXPECT_THROW(gltf_scene(path, 2, notes), UsageError);
}

// Without a camera the scene is framed as --model frames a model; without
// lights it gets --model's lights; it still has no ground and no scaling.
TEST(GltfScene, MissingCameraIsFramedAndMissingLightsAreTheDefaultKeyLight) {
  GltfSpec spec = ground_quad(10.0f);
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(testing::write_gltf("bare.gltf", spec), -1, notes);
  ASSERT_EQ(scene.shapes.size(), 1u);
  EXPECT_EQ(scene.shapes[0].scale, glm::vec3(1.0f));
  Bounds b;
  b.extend({-10, 0, -10});
  b.extend({10, 0, 10});
  EXPECT_EQ(scene.camera, framing_camera(b));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::Spot);
  // Far enough to see the whole 20-unit quad.
  EXPECT_GT(glm::length(scene.camera.position - scene.camera.target), 20.0f);
}

// A card standing over nothing: the camera, the lights and the ground are
// each one assumption; asked for, the ground is added under the card, with
// a material of its own.
TEST(GltfScene, BareSceneNotesItsAssumptionsAndAddsAGroundWhenAsked) {
  GltfSpec spec;
  spec.quads.push_back({{{-1, 0.5f, 0}, {1, 0.5f, 0}, {1, 2.5f, 0}, {-1, 2.5f, 0}}, 0});
  spec.materials.push_back({});
  const std::string path = testing::write_gltf("bare-card.gltf", spec);
  GltfSceneNotes notes;
  const Scene bare = gltf_scene(path, -1, notes);
  ASSERT_EQ(notes.assumptions.size(), 3u);
  EXPECT_NE(notes.assumptions[0].find("has no camera"), std::string::npos);
  EXPECT_NE(notes.assumptions[1].find("has no lights"), std::string::npos);
  EXPECT_NE(notes.assumptions[2].find("has no ground"), std::string::npos);
  EXPECT_TRUE(notes.warnings.empty());
  EXPECT_EQ(bare.shapes.size(), 1u);

  GltfSceneNotes grounded_notes;
  const Scene grounded = gltf_scene(path, -1, grounded_notes, /*ground=*/true);
  ASSERT_EQ(grounded.shapes.size(), 2u);
  const Shape& ground = grounded.shapes[0];
  EXPECT_EQ(ground.kind, ShapeKind::Plane);
  EXPECT_NEAR(ground.position.y, 0.5f, 1e-6f);
  EXPECT_GT(ground.size.x, 10.0f);
  ASSERT_EQ(grounded.materials.size(), bare.materials.size() + 1);
  EXPECT_EQ(ground.material, static_cast<int>(bare.materials.size()));
  EXPECT_EQ(grounded.shapes[1].material, bare.shapes[0].material);
  EXPECT_EQ(grounded.camera, bare.camera);
}

// A ground in the file (a wide face at the bottom, facing up or down) is
// found; a card over a small tile is not grounded by it.
TEST(GltfScene, GroundInTheFileIsFoundAndNothingIsAssumed) {
  GltfSpec spec = ground_quad(3.0f);
  spec.quads.push_back({{{-1, 0.5f, 0}, {1, 0.5f, 0}, {1, 2.5f, 0}, {-1, 2.5f, 0}}, 0});
  spec.cameras.push_back({.position = {0, 4, 6}, .target = {0, 0, 0}});
  spec.lights.push_back({.type = "point", .intensity = 5.0f, .position = {0, 3, 0}});
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(testing::write_gltf("grounded.gltf", spec), -1, notes, true);
  EXPECT_TRUE(notes.assumptions.empty()) << notes.assumptions.front();
  EXPECT_EQ(scene.shapes.size(), 1u);

  TriangleMesh mesh;
  const auto quad = [&](std::array<glm::vec3, 4> c) {
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    for (const glm::vec3& p : c) {
      Vertex v{};
      v.position = p;
      mesh.vertices.push_back(v);
    }
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
  };
  quad({glm::vec3{-1, 0.5f, 0}, {1, 0.5f, 0}, {1, 2.5f, 0}, {-1, 2.5f, 0}});  // the card
  quad({glm::vec3{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}});            // facing down
  EXPECT_TRUE(has_ground(mesh, mesh.bounds()));
  mesh = {};
  quad({glm::vec3{-2, 0.5f, 0}, {2, 0.5f, 0}, {2, 2.5f, 2}, {-2, 2.5f, 2}});
  quad({glm::vec3{-0.3f, 0, -0.3f}, {-0.3f, 0, 0.3f}, {0.3f, 0, 0.3f}, {0.3f, 0, -0.3f}});
  EXPECT_FALSE(has_ground(mesh, mesh.bounds()));
}

TEST(GltfScene, LightsBeyondTheLimitAreDroppedByName) {
  GltfSpec spec = ground_quad();
  for (int i = 0; i < kMaxSceneLights + 2; ++i) {
    spec.lights.push_back({.name = "lamp" + std::to_string(i),
                           .type = "point",
                           .intensity = 5.0f,
                           .position = {0, 3, float(i)}});
  }
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(testing::write_gltf("many-lights.gltf", spec), -1, notes);
  ASSERT_EQ(scene.lights.size(), static_cast<std::size_t>(kMaxSceneLights));
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_NEAR(scene.lights[3].position.z, 3.0f, 1e-5f);
  ASSERT_EQ(notes.warnings.size(), 1u);
  const std::string& w = notes.warnings[0];
  EXPECT_NE(w.find("'lamp4', 'lamp5'"), std::string::npos) << w;
  EXPECT_EQ(w.find("lamp3"), std::string::npos) << w;
}

// glTF (KHR_lights_punctual, "Units" and the reference implementation):
// a point or spot light of I candela gives E = I / d^2 lux on a surface
// facing it (inside a spot's inner cone); a directional light of L lux
// gives L. penumbra's irradiance from a light (lighting.frag's
// incident_light) is colour * intensity / d^2, and colour * intensity for
// a directional light.
TEST(GltfLights, IntensityConversionFollowsTheSpecFormulas) {
  const glm::vec3 color{1.0f, 0.5f, 0.25f};
  for (float candela : {1.0f, 60.0f, 2500.0f}) {
    for (float d : {1.0f, 3.0f, 10.0f}) {
      const float gltf_lux = candela / (d * d);
      for (GltfLightType type : {GltfLightType::Point, GltfLightType::Spot}) {
        const Light l = light_from_gltf(type, color, candela, 0.3f, 0.6f);
        const glm::vec3 penumbra_irradiance = l.color * l.intensity / (d * d);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(penumbra_irradiance[c], color[c] * gltf_lux * kIrradiancePerLux,
                      1e-5f * gltf_lux);
        }
      }
    }
  }
  const Light sun = light_from_gltf(GltfLightType::Directional, color, 3.5f, 0.0f, 0.0f);
  EXPECT_EQ(sun.type, LightType::Directional);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sun.color[c] * sun.intensity, 3.5f * color[c], 1e-5f);
  // Cones: glTF's angles are half-angles in radians.
  const Light spot = light_from_gltf(GltfLightType::Spot, color, 1.0f, 0.3f, 0.6f);
  EXPECT_NEAR(spot.cone_degrees, 0.6f * 180.0f / glm::pi<float>(), 1e-4f);
  EXPECT_NEAR(spot.inner_cone_degrees, 0.3f * 180.0f / glm::pi<float>(), 1e-4f);
  // glTF's default outer cone is pi/4; an outer cone past penumbra's
  // widest is clamped to it.
  EXPECT_EQ(light_from_gltf(GltfLightType::Spot, color, 1.0f, 0.0f, 1.5f).cone_degrees,
            kMaxSpotConeDegrees);
  // A black or negative light is a light of intensity 0, not NaN.
  const Light black = light_from_gltf(GltfLightType::Point, glm::vec3(0.0f), 5.0f, 0, 0);
  EXPECT_EQ(black.intensity, 0.0f);
  EXPECT_EQ(black.color, glm::vec3(1.0f));
}

std::vector<std::uint8_t> checker_rgba(int n) {
  std::vector<std::uint8_t> rgba;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const bool solid = (x + y) % 2 == 0;
      for (const int c : {40 * x, 40 * y, 200, solid ? 255 : 0})
        rgba.push_back(static_cast<std::uint8_t>(c));
    }
  }
  return rgba;
}

// The texture is decoded once, with the material's alpha mode, cutoff,
// doubleSided, sampler and KHR_texture_transform.
TEST(GltfTextures, MaterialReadsTextureAlphaModeAndTransform) {
  testing::write_rgba_png("checker4.png", 4, 4, checker_rgba(4));
  GltfSpec spec = ground_quad();
  spec.materials[0] = {
      .base_color = {1, 1, 1, 0.9f},
      .image = "checker4.png",
      .alpha_mode = "MASK",
      .alpha_cutoff = 0.3f,
      .double_sided = true,
      .texture_transform = R"({"offset": [0.1, 0.2], "rotation": 0.5, "scale": [2, 3]})"};
  const Model model = load_model(testing::write_gltf("textured.gltf", spec));
  ASSERT_EQ(model.materials.size(), 1u);
  const Material& m = model.materials[0];
  ASSERT_NE(m.texture, nullptr);
  EXPECT_EQ(m.texture->width, 4);
  EXPECT_EQ(m.texture->rgba, checker_rgba(4)) << "rows top to bottom, as in the file";
  EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alpha_cutoff, 0.3f);
  EXPECT_FLOAT_EQ(m.alpha, 0.9f);
  EXPECT_TRUE(m.double_sided);
  EXPECT_TRUE(m.nearest_magnification);
  EXPECT_TRUE(model.warnings.empty());
  // KHR_texture_transform: uv' = T(offset) R(rotation) S(scale) uv on glTF's
  // uv (v down); the vertices carry v up.
  const float c = std::cos(0.5f), s = std::sin(0.5f);
  for (const Vertex& v : model.mesh.vertices) {
    const glm::vec2 gltf_uv{v.uv.x, 1.0f - v.uv.y};
    const glm::vec2 scaled = gltf_uv * glm::vec2(2.0f, 3.0f);
    const glm::vec2 expected =
        glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) +
        glm::vec2(0.1f, 0.2f);
    const glm::vec2 t = texture_coordinate(m, v.uv);
    EXPECT_NEAR(t.x, expected.x, 1e-5f);
    EXPECT_NEAR(t.y, expected.y, 1e-5f);
  }
}

// A .glb with its texture embedded in the binary buffer (as exporters
// write them): the texture is decoded from the buffer.
TEST(GltfTextures, GlbWithAnEmbeddedTexture) {
  testing::write_rgba_png("embedded-checker.png", 4, 4, checker_rgba(4));
  GltfSpec spec = ground_quad();
  spec.binary = true;
  spec.materials[0] = {.image = "embedded-checker.png", .alpha_mode = "MASK"};
  spec.cameras.push_back({.position = {0, 3, 3}, .target = {0, 0, 0}});
  const std::string path = testing::write_gltf("embedded.glb", spec);
  std::filesystem::remove(std::filesystem::path(path).parent_path() / "embedded-checker.png");
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(path, -1, notes);
  ASSERT_EQ(scene.materials.size(), 1u);
  ASSERT_NE(scene.materials[0].texture, nullptr);
  EXPECT_EQ(scene.materials[0].texture->rgba, checker_rgba(4));
  EXPECT_EQ(scene.materials[0].alpha_mode, AlphaMode::Mask);
  expect_near(scene.camera.position, {0, 3, 3}, 1e-5f);
  EXPECT_TRUE(notes.warnings.empty());
}

// A texture that is missing or not an image: one warning naming it, and
// the flat colour; the model still loads.
TEST(GltfTextures, MissingOrBrokenTextureIsAWarningAndTheFlatColour) {
  testing::write_model_file("not-an-image.png", "this is not a PNG file");
  for (const std::string image : {"no-such-texture.png", "not-an-image.png"}) {
    GltfSpec spec = ground_quad();
    spec.materials[0] = {.base_color = {0.2f, 0.4f, 0.6f, 1.0f}, .image = image};
    const Model model = load_model(testing::write_gltf("broken-texture.gltf", spec));
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_EQ(model.materials[0].texture, nullptr);
    EXPECT_NEAR(model.materials[0].albedo.g, 0.4f, 1e-6f);
    ASSERT_EQ(model.warnings.size(), 1u);
    EXPECT_NE(model.warnings[0].find(image), std::string::npos) << model.warnings[0];
    EXPECT_EQ(model.warnings[0].find('\n'), std::string::npos);
  }
}

// Texture coordinates outside [0, 1] wrap as the sampler says: repeat,
// mirrored repeat, or clamp to the edge.
TEST(GltfTextures, OutOfRangeCoordinatesWrapAsTheSamplerSays) {
  auto image = std::make_shared<TextureImage>();
  image->width = 4;
  image->height = 1;
  for (int x = 0; x < 4; ++x)
    for (const int c : {255, 255, 255, 60 * x}) image->rgba.push_back(static_cast<std::uint8_t>(c));
  Material m;
  m.texture = image;
  m.nearest_magnification = true;
  const auto alpha_at = [&](float s) { return sample_texture(m, {s, 0.5f}).a * 255.0f; };
  m.wrap_s = TextureWrap::Repeat;
  EXPECT_NEAR(alpha_at(1.125f), 0.0f, 1e-3f);
  EXPECT_NEAR(alpha_at(-0.125f), 180.0f, 1e-3f);
  m.wrap_s = TextureWrap::MirroredRepeat;
  EXPECT_NEAR(alpha_at(1.125f), 180.0f, 1e-3f);
  EXPECT_NEAR(alpha_at(-0.125f), 0.0f, 1e-3f);
  m.wrap_s = TextureWrap::ClampToEdge;
  EXPECT_NEAR(alpha_at(7.0f), 180.0f, 1e-3f);
  EXPECT_NEAR(alpha_at(-7.0f), 0.0f, 1e-3f);
  // A non-finite coordinate reads texel 0, not memory anywhere.
  EXPECT_NEAR(alpha_at(std::nanf("")), 0.0f, 1e-3f);
}

// The tracer's view of cut-outs: a ray through a hole passes, through the
// solid part it does not, and a single-sided card stops rays only from
// its front's side.
TEST(CasterCutouts, HolesAndBacksLetShadowRaysThrough) {
  testing::write_rgba_png("checker2.png", 2, 2, checker_rgba(2));
  GltfSpec spec;
  spec.quads.push_back({{{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}}, 0});  // faces +y
  spec.materials.push_back({.image = "checker2.png", .alpha_mode = "MASK"});
  Scene scene;
  Shape shape;
  attach_model(scene, shape, testing::write_gltf("cutout-card.gltf", spec), true);
  scene.shapes.push_back(shape);
  const TriangleMesh mesh = build_scene_mesh(scene);
  const CasterCutouts cutouts(mesh, scene.materials);
  ASSERT_TRUE(cutouts.any());
  EXPECT_NE(cutouts.hash(), 0u);
  // Triangle 0 is corners 0, 1, 2: barycentrics (u, v) weigh corners 1, 2.
  // Corner 0 (uv 0,0: texel (0,0), solid); near corner 1 (uv 1,0: texel
  // (1,0), a hole).
  const glm::vec3 up{0, 1, 0};
  EXPECT_FALSE(cutouts.passes(0, 0.05f, 0.05f, up)) << "solid texel";
  EXPECT_TRUE(cutouts.passes(0, 0.9f, 0.05f, up)) << "hole texel";
  EXPECT_TRUE(cutouts.passes(0, 0.05f, 0.05f, -up)) << "the back of a single-sided card";
  scene.materials[0].double_sided = true;
  EXPECT_FALSE(CasterCutouts(mesh, scene.materials).passes(0, 0.05f, 0.05f, -up));
}

// An extension the file requires and penumbra does not know: the file is
// read (what the reader understands of it), not refused silently either way.
TEST(GltfScene, UnknownRequiredExtensionIsAnErrorNamingIt) {
  GltfSpec spec = ground_quad();
  spec.extensions_required.push_back("EXT_made_up_extension");
  const std::string path = testing::write_gltf("unknown-extension.gltf", spec);
  try {
    GltfSceneNotes notes;
    (void)gltf_scene(path, -1, notes);
    FAIL() << "loaded a file requiring an unknown extension";
  } catch (const RuntimeError& e) {
    EXPECT_NE(std::string(e.what()).find("EXT_made_up_extension"), std::string::npos) << e.what();
  }
}

// An extension the file only uses (not requires) is ignored, with one
// warning naming it.
TEST(GltfScene, UnknownUsedExtensionIsAWarningNamingIt) {
  GltfSpec spec = ground_quad();
  spec.extensions_used.push_back("EXT_also_made_up");
  GltfSceneNotes notes;
  const Scene scene = gltf_scene(testing::write_gltf("used-extension.gltf", spec), -1, notes);
  EXPECT_EQ(scene.shapes.size(), 1u);
  ASSERT_EQ(notes.warnings.size(), 1u);
  EXPECT_NE(notes.warnings[0].find("EXT_also_made_up"), std::string::npos) << notes.warnings[0];
}

}  // namespace
}  // namespace penumbra

namespace penumbra {
namespace {

// OBJ: map_Kd is the base-colour texture and map_d its alpha mask.
TEST(ObjTextures, MapKdAndMapDMakeAMaskedTexture) {
  std::vector<std::uint8_t> colour, mask;
  for (int i = 0; i < 4; ++i) {
    for (const int c : {200, 100, 50, 255}) colour.push_back(static_cast<std::uint8_t>(c));
    for (const int c : {i < 2 ? 255 : 0, 0, 0, 255}) mask.push_back(static_cast<std::uint8_t>(c));
  }
  testing::write_rgba_png("obj-card/colour.png", 2, 2, colour);
  testing::write_rgba_png("obj-card/mask.png", 2, 2, mask);
  testing::write_model_file("obj-card/card.mtl",
                            "newmtl leaf\nKd 1 1 1\nmap_Kd colour.png\nmap_d mask.png\n");
  const Model model = load_model(testing::write_model_file(
      "obj-card/card.obj",
      "mtllib card.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "usemtl leaf\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"));
  ASSERT_EQ(model.materials.size(), 1u);
  const Material& m = model.materials[0];
  ASSERT_NE(m.texture, nullptr);
  EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
  EXPECT_TRUE(m.double_sided) << "OBJ has no sidedness: double-sided";
  // Colour from map_Kd, alpha from map_d's grey level (it has no alpha).
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(m.texture->rgba[4 * i], 200);
    EXPECT_EQ(m.texture->rgba[4 * i + 3], i < 2 ? 255 : 0);
  }
  // OBJ's vt has v up: the mask's top row (solid) is at v near 1, its
  // bottom row (holes) at v near 0.
  EXPECT_TRUE(is_cut_out(m, 1.0f, glm::vec2(0.25f, 0.25f)));
  EXPECT_FALSE(is_cut_out(m, 1.0f, glm::vec2(0.25f, 0.75f)));
}

// Vertex colours (here a PLY's red, green, blue) reach the vertices.
TEST(VertexColors, PlyColoursAreRead) {
  const Model model = load_model(testing::write_model_file(
      "coloured.ply",
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n"));
  ASSERT_EQ(model.mesh.vertices.size(), 3u);
  std::vector<glm::vec4> colours;
  for (const Vertex& v : model.mesh.vertices) colours.push_back(unpack_color(v.color));
  for (const glm::vec4& expected :
       {glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1), glm::vec4(0, 0, 1, 1)}) {
    EXPECT_NE(std::find(colours.begin(), colours.end(), expected), colours.end())
        << expected.r << " " << expected.g << " " << expected.b;
  }
}

}  // namespace
}  // namespace penumbra
