// `penumbra compare` end to end on a tiny view: the table, the JSON, the
// images, the reference cache, and its usage errors (each found before
// anything is written).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using penumbra::testing::is_one_error_line;
using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;

const std::string kSmall = "--width 48 --height 32 --shadow-map-size 128 ";

std::string cache_dir(const std::string& name) {
  return out_path("compare-cache-" + name);
}

// The command fails with the status and one line naming the culprit, and
// neither the image folder nor the JSON file appears.
void expect_compare_error(const std::string& args, int status, const std::string& culprit) {
  const std::string dir = out_path("compare-error-out");
  const std::string json = out_path("compare-error.json");
  const std::string cache = cache_dir("error");
  Result r = run("compare " + kSmall + args + " --cache-dir " + cache + " --json " + json +
                 ((" " + args).find(" -o ") == std::string::npos ? " -o " + dir : ""));
  EXPECT_EQ(r.status, status) << args << "\n" << r.err;
  EXPECT_TRUE(is_one_error_line(r.err, culprit)) << args << "\nstderr: " << r.err;
  EXPECT_TRUE(r.out.empty()) << args << "\nstdout: " << r.out;
  EXPECT_FALSE(fs::exists(dir)) << "image folder made for: " << args;
  EXPECT_FALSE(fs::exists(json)) << "JSON written for: " << args;
  EXPECT_FALSE(fs::exists(cache)) << "cache written for: " << args;
}

TEST(Compare, UsageErrors) {
  expect_compare_error("--techniques hard,blurry", 2, "'blurry'");
  expect_compare_error("--techniques ''", 2, "--technique");
  expect_compare_error("--filter box", 2, "'box'");
  expect_compare_error("--scene nosuchscene", 2, "nosuchscene");
  expect_compare_error("--light-index 3", 2, "--light-index");
  expect_compare_error("--reference-samples 0", 2, "--reference-samples");
  expect_compare_error("--light-size -1", 2, "--light-size");
  expect_compare_error("--techniques esm --filter sat", 2, "nothing to compare");
  expect_compare_error("--no-such-flag", 2, "--no-such-flag");
}

TEST(Compare, RunTimeErrors) {
  expect_compare_error("--scene " + out_path("missing.json"), 1, "missing.json");
}

TEST(Compare, BadOutputPaths) {
  expect_compare_error("-o " + out_path("no-such-folder") + "/images", 2, "does not exist");
  // procfs refuses new files and folders even to root.
  expect_compare_error("-o /proc/self/images", 2, "not writable");
  const std::string file = out_path("compare-a-file");
  std::ofstream(file) << "x";
  expect_compare_error("-o " + file, 2, "is not a folder");
  const std::string dir = out_path("compare-bad-json");
  const std::string cache = cache_dir("bad-json");
  Result r = run("compare " + kSmall + "--cache-dir " + cache + " -o " + dir + " --json " +
                 out_path("no-such-folder") + "/x.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(is_one_error_line(r.err, "does not exist")) << r.err;
  EXPECT_FALSE(fs::exists(dir));
}

// Hard and filtered techniques against a point light's traced shadow; esm
// with sat is reported as skipped while the rest run; the numbers, the
// images and the cache all appear, and a second run finds the reference
// in the cache.
TEST(Compare, WritesTableJsonImagesAndCache) {
  const std::string dir = out_path("compare-out");
  const std::string json_path = out_path("compare.json");
  const std::string cache = cache_dir("ok");
  const std::string args = "compare " + kSmall +
                           "--techniques hard,esm,msm --filter all --light-size 0 --cache-dir " +
                           cache + " -o " + dir + " --json " + json_path;
  Result r = run(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("technique"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("skipped: --technique esm cannot use --filter sat"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("point light, 1 ray per pixel"), std::string::npos) << r.out;

  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["scene"], "default");
  EXPECT_EQ(j["width"], 48);
  EXPECT_EQ(j["reference"]["cached"], false);
  EXPECT_GT(j["reference"]["pixels"].get<long>(), 100);
  // The tracer's speed: at least one ray per judged pixel (pixels outside
  // the spot's cone are traced but not judged), at most one per pixel.
  const long rays = j["reference"]["rays_traced"].get<long>();
  EXPECT_GE(rays, j["reference"]["pixels"].get<long>());
  EXPECT_LE(rays, 48L * 32L);
  EXPECT_GT(j["reference"]["rays_per_second"].get<double>(), 0.0);
  EXPECT_GT(j["reference"]["rays_per_cpu_second"].get<double>(), 0.0);
  const auto& results = j["results"];
  ASSERT_EQ(results.size(), 5u);  // hard; esm gaussian, esm sat; msm gaussian, msm sat
  int ok = 0;
  for (const auto& item : results) {
    if (item["status"] == "skipped") {
      EXPECT_EQ(item["technique"], "esm");
      EXPECT_EQ(item["filter"], "sat");
      continue;
    }
    ++ok;
    const bool filtered = item["technique"] != "hard";
    for (const char* reference : {"traced", "filtered"}) {
      if (!filtered && std::string(reference) == "filtered") {
        EXPECT_TRUE(item[reference].is_null());
        continue;
      }
      const auto& m = item[reference];
      EXPECT_EQ(m["pixels"], j["reference"]["pixels"]) << reference;
      for (const char* key : {"mae", "rmse", "max_error", "leak_fraction", "over_dark_fraction"}) {
        EXPECT_GE(m[key].get<double>(), 0.0) << key;
        EXPECT_LE(m[key].get<double>(), 1.0) << key;
      }
      EXPECT_LE(m["mae"].get<double>(), m["rmse"].get<double>());
    }
    for (const auto& [name, path] : item["images"].items()) {
      EXPECT_TRUE(fs::exists(path.get<std::string>())) << name;
    }
    EXPECT_EQ(item["images"].size(), filtered ? 4u : 2u);
  }
  EXPECT_EQ(ok, 4);
  EXPECT_TRUE(fs::exists(fs::path(dir) / "reference-traced.png"));
  EXPECT_TRUE(fs::exists(fs::path(dir) / "msm-sat-w2-error-filtered.png"));
  // The compared images also as OpenEXR (magic 76 2f 31 01); the
  // colour-mapped error images only as PNG.
  for (const char* name :
       {"reference-traced", "hard", "msm-sat-w2", "msm-sat-w2-reference-filtered"}) {
    const fs::path exr = fs::path(dir) / (std::string(name) + ".exr");
    std::ifstream file(exr, std::ios::binary);
    ASSERT_TRUE(file) << exr;
    unsigned char magic[4] = {};
    file.read(reinterpret_cast<char*>(magic), 4);
    EXPECT_TRUE(magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01)
        << exr;
  }
  EXPECT_FALSE(fs::exists(fs::path(dir) / "hard-error-traced.exr"));
  int cached = 0;
  for (const auto& entry : fs::directory_iterator(cache)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);
    ++cached;
  }
  EXPECT_EQ(cached, 1);

  Result again = run(args);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("1 ray per pixel, cached"), std::string::npos) << again.out;
  std::ifstream in2(json_path);
  const nlohmann::json j2 = nlohmann::json::parse(in2);
  EXPECT_EQ(j2["reference"]["cached"], true);
  EXPECT_TRUE(j2["reference"]["rays_per_second"].is_null()) << "nothing traced";
}

// An area light: the table names it, and without -o, --json or a cache
// nothing is written.
TEST(Compare, AreaLightReferenceWithoutOutputs) {
  Result r = run("compare " + kSmall +
                 "--techniques pcss --light-size 0.8 --reference-samples 16 --no-cache");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("square light 0.8 wide, 16 rays per pixel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pcss"), std::string::npos) << r.out;
}

// --soft measures the moment techniques' soft shadows (from the
// summed-area table) against the traced area-light shadow; a technique in
// the list that cannot be soft (hard) is measured as usual; and --soft with
// nothing that can be soft is a usage error.
TEST(Compare, SoftMomentShadows) {
  const std::string json_path = out_path("compare-soft.json");
  const std::string dir = out_path("compare-soft-out");
  Result r = run("compare " + kSmall +
                 "--soft --filter sat --techniques hard,vsm,msm,msm16 --light-size 0.8 "
                 "--reference-samples 16 --no-cache -o " +
                 dir + " --json " + json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("sat, soft"), std::string::npos) << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& results = j["results"];
  ASSERT_EQ(results.size(), 4u);
  for (const auto& item : results) {
    const std::string technique = item["technique"];
    ASSERT_EQ(item["status"], "ok") << technique;
    const auto& m = item["traced"];
    EXPECT_EQ(m["pixels"], j["reference"]["pixels"]) << technique;
    EXPECT_GE(m["mae"].get<double>(), 0.0) << technique;
    EXPECT_LE(m["mae"].get<double>(), m["rmse"].get<double>()) << technique;
    if (technique == "hard") {
      EXPECT_EQ(item["soft"], false);
      continue;
    }
    EXPECT_EQ(item["soft"], true) << technique;
    EXPECT_EQ(item["filter"], "sat") << technique;
    // Each pixel's kernel follows its penumbra: no fixed-kernel reference.
    EXPECT_TRUE(item["filtered"].is_null()) << technique;
    EXPECT_TRUE(fs::exists(fs::path(dir) / (technique + "-sat-w2-soft.png"))) << technique;
  }
  expect_compare_error("--soft --techniques hard,pcss", 2, "--soft");
  expect_compare_error("--soft --techniques vsm,msm --filter gaussian", 2, "--soft");
  expect_compare_error("--soft --techniques esm --filter all", 2, "--soft");
}

// compare takes render's camera flags: the view measured is the one given
// (echoed in the JSON), not the scene's own; a degenerate camera is a
// usage error before anything is written.
TEST(Compare, MeasuresTheCameraGiven) {
  const auto measure = [](const std::string& camera) {
    const std::string json_path = out_path("compare-camera.json");
    const Result r = run("compare " + kSmall + "--techniques hard --light-size 0 --no-cache " +
                         camera + " --json " + json_path);
    EXPECT_EQ(r.status, 0) << camera << "\n" << r.err;
    std::ifstream in(json_path);
    return nlohmann::json::parse(in);
  };
  const nlohmann::json scene_camera = measure("");
  const nlohmann::json given =
      measure("--camera-position 3,4,5 --camera-target 0,0.5,0 --camera-fov 30");
  EXPECT_EQ(given["camera"]["position"], nlohmann::json({3.0, 4.0, 5.0}));
  EXPECT_EQ(given["camera"]["target"], nlohmann::json({0.0, 0.5, 0.0}));
  EXPECT_EQ(given["camera"]["fov_y_degrees"], 30.0);
  EXPECT_NE(scene_camera["camera"], given["camera"]);
  EXPECT_NE(scene_camera["reference"]["pixels"], given["reference"]["pixels"])
      << "the same pixels judged from another camera";
  expect_compare_error("--camera-position 1,2,3 --camera-target 1,2,3", 2, "--camera-position");
  expect_compare_error("--camera-fov 0", 2, "--camera-fov");
}

TEST(Compare, HelpListsItsOptions) {
  Result r = run("compare --help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--scene", "--techniques", "--filter", "--blur", "--light-size",
                             "--sun-angle", "--reference-samples", "--json", "--output",
                             "--cache-dir", "--no-cache", "--light-index", "--width"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option << " missing from --help";
  }
  EXPECT_NE(r.out.find("--soft applies to vsm, msm and msm16 with --filter sat"), std::string::npos)
      << r.out;
}

}  // namespace

// The near and far halves partition the compared pixels (their squared
// errors add up to the whole's), the table shows them with --by-distance,
// and the light's texel density is measured over the same pixels.
TEST(Compare, NearAndFarHalvesAndTexelDensity) {
  const std::string dir = out_path("compare-halves-out");
  const std::string json_path = out_path("compare-halves.json");
  Result r =
      run("compare " + kSmall + "--techniques hard --light-size 0 --by-distance --no-cache -o " +
          dir + " --json " + json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("traced, near"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("traced, far"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("texel density"), std::string::npos) << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const long pixels = j["reference"]["pixels"].get<long>();
  const auto& halves = j["distance_halves"];
  const long near_pixels = halves["near_pixels"].get<long>();
  const long far_pixels = halves["far_pixels"].get<long>();
  EXPECT_EQ(near_pixels + far_pixels, pixels);
  EXPECT_LE(std::abs(near_pixels - far_pixels), pixels / 10) << "split at the median";
  EXPECT_GT(halves["median_distance"].get<double>(), 0.0);
  const auto& hard = j["results"][0];
  EXPECT_EQ(hard["traced_near"]["pixels"].get<long>(), near_pixels);
  EXPECT_EQ(hard["traced_far"]["pixels"].get<long>(), far_pixels);
  const double near_rmse = hard["traced_near"]["rmse"].get<double>();
  const double far_rmse = hard["traced_far"]["rmse"].get<double>();
  const double whole = std::sqrt((near_rmse * near_rmse * static_cast<double>(near_pixels) +
                                  far_rmse * far_rmse * static_cast<double>(far_pixels)) /
                                 static_cast<double>(pixels));
  EXPECT_NEAR(whole, hard["traced"]["rmse"].get<double>(), 1e-9);
  const auto& density = j["texel_density"];
  EXPECT_EQ(density["judged"]["pixels"].get<long>(), pixels);
  EXPECT_LE(density["shadowed"]["pixels"].get<long>(), pixels);
  EXPECT_GT(density["shadowed"]["pixels"].get<long>(), 0);
  for (const char* set : {"judged", "shadowed"}) {
    EXPECT_GT(density[set]["median"].get<double>(), 0.0) << set;
    EXPECT_GE(density[set]["at_least_one"].get<double>(), 0.0) << set;
    EXPECT_LE(density[set]["at_least_one"].get<double>(), 1.0) << set;
  }
  EXPECT_TRUE(fs::exists(density["image"].get<std::string>()));
}
