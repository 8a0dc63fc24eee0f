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

const std::string kSmall = " --width 48 --height 32 --shadow-map-size 256";

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
  const Result r = run("render --scene " + scene + kSmall + " -o " + png);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  EXPECT_EQ(r.err.rfind("penumbra: warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("cli-missing-leaf.png: no such file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

TEST(CliGltf, CameraIndexIsCheckedAgainstTheFile) {
  const std::string scene = write_gltf("cli-one-camera.gltf", quad_scene());
  const std::string png = out_path("gltf-camera.png");
  EXPECT_EQ(run("render --scene " + scene + " --camera-index 0" + kSmall + " -o " + png).status, 0);
  expect_error("render --scene " + scene + " --camera-index 1" + kSmall, 2, "--camera-index",
               out_path("gltf-camera-1.png"));
  expect_error("render --scene default --camera-index 0" + kSmall, 2, "--camera-index",
               out_path("gltf-camera-default.png"));
}

TEST(CliGltf, RequiredUnknownExtensionIsOneErrorNamingIt) {
  GltfSpec spec = quad_scene();
  spec.extensions_required.push_back("KHR_draco_mesh_compression");
  const std::string scene = write_gltf("cli-draco.gltf", spec);
  expect_error("render --scene " + scene + kSmall, 1, "KHR_draco_mesh_compression",
               out_path("gltf-draco.png"));
}

}  // namespace
