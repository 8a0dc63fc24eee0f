// glTF scenes through the real binary: `--scene FILE.gltf` renders with
// the file's camera, `--camera-index` is checked, and missing textures,
// unknown extensions and bad camera indices behave as documented.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_run.hpp"
#include "gltf_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::expect_error;
using penumbra::testing::GltfSpec;
using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;
using penumbra::testing::write_gltf;

const std::string kSmallGltf = " --width 48 --height 32 --shadow-map-size 256";

GltfSpec quad_scene() {
  GltfSpec spec;
  spec.quads.push_back({{{-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}}, 0});
  spec.materials.push_back({});
  spec.cameras.push_back({.position = {0, 4, 4}, .target = {0, 0, 0}});
  spec.lights.push_back({.type = "spot", .intensity = 20, .position = {0, 5, 0}});
  return spec;
}

// A missing texture: exactly one warning line naming it, the image is
// written, exit status 0.
TEST(CliGltf, MissingTextureIsOneWarningAndTheSceneRenders) {
  GltfSpec spec = quad_scene();
  spec.materials[0].image = "cli-missing-leaf.png";
  const std::string scene = write_gltf("cli-missing-texture.gltf", spec);
  const std::string png = out_path("gltf-missing-texture.png");
  const Result r = run("render --scene " + scene + kSmallGltf + " -o " + png);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  EXPECT_EQ(r.err.rfind("penumbra: warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("cli-missing-leaf.png: no such file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(CliGltf, CameraIndexIsCheckedAgainstTheFile) {
  const std::string scene = write_gltf("cli-one-camera.gltf", quad_scene());
  const std::string png = out_path("gltf-camera.png");
  EXPECT_EQ(run("render --scene " + scene + " --camera-index 0" + kSmallGltf + " -o " + png).status,
            0);
  expect_error("render --scene " + scene + " --camera-index 1" + kSmallGltf, 2, "--camera-index",
               out_path("gltf-camera-1.png"));
  expect_error("render --scene default --camera-index 0" + kSmallGltf, 2, "--camera-index",
               out_path("gltf-camera-default.png"));
}

TEST(CliGltf, RequiredUnknownExtensionIsOneErrorNamingIt) {
  GltfSpec spec = quad_scene();
  spec.extensions_required.push_back("KHR_draco_mesh_compression");
  const std::string scene = write_gltf("cli-draco.gltf", spec);
  expect_error("render --scene " + scene + kSmallGltf, 1, "KHR_draco_mesh_compression",
               out_path("gltf-draco.png"));
}

// A bare file (one card, no camera, lights or ground): one note line per
// assumption and nothing else; --ground on adds a ground, which shadows
// the final image; --ground is refused for scenes that are not glTF.
TEST(CliGltf, BareSceneNotesEachAssumptionAndGroundAddsOne) {
  GltfSpec spec;
  spec.quads.push_back({{{-1, 0.5f, 0}, {1, 0.5f, 0}, {1, 2.5f, 0}, {-1, 2.5f, 0}}, 0});
  spec.materials.push_back({.double_sided = true});
  const std::string scene = write_gltf("cli-bare.gltf", spec);
  const std::string png = out_path("gltf-bare.png");
  const Result r = run("render --scene " + scene + kSmallGltf + " -o " + png);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  int lines = 0;
  for (std::size_t at = 0; at < r.err.size(); at = r.err.find('\n', at) + 1) {
    EXPECT_EQ(r.err.compare(at, 16, "penumbra: note: "), 0) << r.err;
    ++lines;
  }
  EXPECT_EQ(lines, 3) << r.err;
  for (const char* what : {"has no camera", "has no lights", "has no ground: none added"}) {
    EXPECT_NE(r.err.find(what), std::string::npos) << what << ": " << r.err;
  }
  const Result g = run("render --scene " + scene + " --ground on" + kSmallGltf + " -o " + png);
  EXPECT_EQ(g.status, 0) << g.err;
  EXPECT_NE(g.err.find("has no ground: added"), std::string::npos) << g.err;
  expect_error("render --scene default --ground on" + kSmallGltf, 2, "--ground",
               out_path("gltf-ground-default.png"));
  expect_error("render --model " + scene + " --ground on" + kSmallGltf, 2, "--ground",
               out_path("gltf-ground-model.png"));
}

// A file with its own camera, lights and ground assumes nothing.
TEST(CliGltf, CompleteSceneHasNoNotes) {
  const std::string scene = write_gltf("cli-complete.gltf", quad_scene());
  const Result r =
      run("render --scene " + scene + kSmallGltf + " -o " + out_path("gltf-complete.png"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

}  // namespace
