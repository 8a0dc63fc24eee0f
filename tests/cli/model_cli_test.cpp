// `--model` and model shapes in scene files through the real binary: they
// render, and every broken model ends in one error line naming the file,
// exit status 1 and no output.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_run.hpp"
#include "model_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::expect_error;
using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;
using penumbra::testing::tetrahedron_obj;
using penumbra::testing::write_model_file;

const std::string kSmallModel = " --width 64 --height 48 --shadow-map-size 256";

TEST(CliModel, RendersAModelFile) {
  const std::string model = write_model_file("cli-tet.obj", tetrahedron_obj());
  for (const char* technique : {"hard", "pcss"}) {
    const std::string png = out_path(std::string("model-") + technique + ".png");
    const Result r =
        run("render --model " + model + kSmallModel + " --technique " + technique + " -o " + png);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(png)) << technique;
  }
}

TEST(CliModel, RendersASceneFileWithAModel) {
  write_model_file("cli-scene/models/tet.obj", tetrahedron_obj());
  const std::string scene = write_model_file("cli-scene/scene.json", R"({
    "lights": [{"type": "spot", "position": [2, 6, 3], "target": [0, 0, 0]},
               {"type": "directional", "direction": [0.7, -1, -0.25], "intensity": 0.3}],
    "objects": [{"shape": "plane", "size": [8, 0, 8]},
                {"shape": "model", "file": "models/tet.obj", "scale": [1.5, 2, 1.5],
                 "position": [0, 0, 0], "rotation": [0, 30, 0]}]
  })");
  const std::string png = out_path("model-scene.png");
  const Result r = run("render --scene " + scene + kSmallModel + " -o " + png);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
}

TEST(CliModel, CompareAndBenchTakeAModel) {
  const std::string model = write_model_file("cli-bench-tet.obj", tetrahedron_obj());
  const std::string json = out_path("model-compare.json");
  Result r = run("compare --model " + model + kSmallModel +
                 " --techniques hard --reference-samples 4 --no-cache --json " + json);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(json));
  const std::string bench = out_path("model-bench.json");
  r = run("bench --model " + model + kSmallModel +
          " --technique hard --frames 1 --warmup 0 --json " + bench);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(bench));
}

TEST(CliModel, BrokenModelsAreOneErrorNamingTheFile) {
  const std::string out = out_path("broken-model.png");
  const std::string missing = write_model_file("cli-placeholder.txt", "") + ".missing.obj";
  expect_error("render --model " + missing, 1, missing + ": no such file", out);
  std::string garbage;
  for (int i = 0; i < 2000; ++i) garbage += static_cast<char>((i * 7919) % 251);
  for (const auto& [name, content] : std::initializer_list<std::pair<std::string, std::string>>{
           {"cli-garbage.ply", garbage},
           {"cli-garbage.obj", garbage},
           {"cli-truncated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2"},
           {"cli-empty.obj", ""},
           {"cli-no-faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"},
           {"cli-range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"},
           {"cli-nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
           {"cli-inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n"}}) {
    const std::string path = write_model_file(name, content);
    expect_error("render --model " + path + kSmallModel, 1, path + ": ", out);
  }
  // The other commands read the model before writing anything too.
  const std::string range = write_model_file("cli-range.obj", "v 0 0 0\nf 1 1 7\n");
  expect_error("compare --model " + range + " --no-cache", 1, range + ": ", out_path("cmp.json"),
               "--json");
  expect_error("bench --model " + range, 1, range + ": ", out_path("bench.json"), "--json");
  expect_error("report --model " + range + " --quick", 1, range + ": ", out_path("report-dir"));
}

TEST(CliModel, SceneFileWithABrokenModelNamesBoth) {
  write_model_file("cli-bad-scene/nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string scene =
      write_model_file("cli-bad-scene/scene.json",
                       R"({"lights": [{}], "objects": [{"shape": "model", "file": "nan.obj"}]})");
  const std::string out = out_path("bad-scene-model.png");
  expect_error("render --scene " + scene, 1, "/objects/0/file: ", out);
  expect_error("render --scene " + scene, 1, "cli-bad-scene/nan.obj: mesh 0, vertex 0", out);
}

TEST(CliModel, ModelAndSceneTogetherIsAUsageError) {
  const std::string model = write_model_file("cli-both.obj", tetrahedron_obj());
  expect_error("render --scene spot --model " + model, 2, "--model", out_path("both.png"));
  expect_error("bench --model " + model + " --scene default", 2, "--scene", out_path("both.json"),
               "--json");
}

TEST(CliModel, HelpOfEveryCommandOffersModel) {
  for (const char* command : {"render", "compare", "bench", "report", "view"}) {
    const Result r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_NE(r.out.find("--model"), std::string::npos) << command;
    EXPECT_NE(r.out.find("--scene"), std::string::npos) << command;
  }
}

}  // namespace
