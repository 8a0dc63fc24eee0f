// The real binary with bad inputs: one "penumbra: error:" line naming the
// culprit, the documented exit status, and no output file left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "cli/cli_run.hpp"
#include "penumbra/shadow/virtual_clipmap.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::expect_error;
using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;

// Runs `bench ARGS --json FILE` (FILE a test output named `name`) and
// returns the JSON it wrote.
nlohmann::json bench_json(const std::string& args, const std::string& name) {
  const std::string path = out_path(name);
  const Result r = run("bench " + args + " --json " + path);
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, false);
}

TEST(Cli, UsageErrorsExitWithStatus2) {
  const std::string out = out_path("bad.png");
  expect_error("render --scene nosuchscene", 2, "nosuchscene", out);
  expect_error("render --technique blurry", 2, "blurry", out);
  expect_error("render --view sideways", 2, "sideways", out);
  expect_error("render --shadow-map-size 0", 2, "--shadow-map-size", out);
  expect_error("render --shadow-map-size -5", 2, "--shadow-map-size", out);
  expect_error("render --shadow-map-size 99999", 2, "--shadow-map-size", out);
  expect_error("render --shadow-map-size 1e3", 2, "--shadow-map-size", out);
  expect_error("render --width 0", 2, "--width", out);
  expect_error("render --height abc", 2, "--height", out);
  expect_error("render --constant-bias nan", 2, "--constant-bias", out);
  expect_error("render --slope-bias -1", 2, "--slope-bias", out);
  expect_error("render --light-size inf", 2, "--light-size", out);
  expect_error("render --no-such-flag", 2, "--no-such-flag", out);
  expect_error("render --view shadow --light-index 3", 2, "--light-index", out);
}

TEST(Cli, FilteredTechniqueUsageErrors) {
  const std::string out = out_path("filtered.png");
  expect_error("render --technique msm --blur -1", 2, "--blur", out);
  expect_error("render --technique msm --blur 1000", 2, "--blur", out);
  expect_error("render --technique esm --esm-c 0", 2, "--esm-c", out);
  expect_error("render --technique esm --esm-c 200", 2, "--esm-c", out);
  expect_error("render --technique msm --msm-alpha 0", 2, "--msm-alpha", out);
  expect_error("render --technique msm --msm-alpha 1", 2, "--msm-alpha", out);
  expect_error("render --technique msm16 --msm16-alpha -0.1", 2, "--msm16-alpha", out);
  expect_error("render --technique vsm --bleed-reduction 1", 2, "--bleed-reduction", out);
  expect_error("render --technique vsm --vsm-min-variance nan", 2, "--vsm-min-variance", out);
  expect_error("render --technique msm --filter box", 2, "box", out);
  expect_error("render --technique esm --filter sat", 2, "--filter sat", out);
  expect_error("render --technique evsm2 --filter sat", 2, "--filter sat", out);
  expect_error("render --technique evsm4 --filter sat --blur 4", 2, "--filter sat", out);
  expect_error("render --technique evsm4 --evsm-positive 43", 2, "--evsm-positive", out);
  expect_error("render --technique evsm4 --evsm-negative 0", 2, "--evsm-negative", out);
  expect_error("render --technique msm --fused maybe", 2, "--fused", out);
  expect_error("render --technique hard --view moments", 2, "--view moments", out);
  expect_error("render --technique pcf --pcf-samples 0", 2, "--pcf-samples", out);
  expect_error("render --technique pcf --pcf-samples 65", 2, "--pcf-samples", out);
  expect_error("render --technique pcf --pcf-width -1", 2, "--pcf-width", out);
  expect_error("render --technique pcss --light-size -0.5", 2, "--light-size", out);
  expect_error("render --technique pcss --pcss-blocker-samples 0", 2, "--pcss-blocker-samples",
               out);
  expect_error("render --technique pcss --sun-angle 90", 2, "--sun-angle", out);
  expect_error("render --technique msm --soft", 2, "--soft", out);
  expect_error("render --technique pcss --filter sat --soft", 2, "--soft", out);
  expect_error("render --technique esm --filter sat --soft", 2, "--soft", out);
}

// A smoke test, not a speed test: every pass is present with a time.
TEST(Cli, BenchWritesJsonWithEveryPass) {
  const nlohmann::json j = bench_json(
      "--frames 2 --warmup 1 --technique msm,vsm --filter gaussian --blur 2 --fused off "
      "--width 64 --height 48 --shadow-map-size 256",
      "bench.json");
  ASSERT_TRUE(j.contains("renderer"));
  EXPECT_FALSE(j.at("renderer").get<std::string>().empty());
  ASSERT_EQ(j.at("runs").size(), 2u);
  for (const auto& run : j.at("runs")) {
    for (const char* pass : {"shadow depth", "resolve", "filter H", "filter V", "G-buffer",
                             "lighting", "copy (yardstick)"}) {
      ASSERT_TRUE(run.at("passes").contains(pass)) << pass;
      const auto& p = run.at("passes").at(pass);
      EXPECT_GT(p.at("wall_median_ms").get<double>(), 0.0) << pass;
      EXPECT_GE(p.at("median_ms").get<double>(), 0.0) << pass;
      EXPECT_LE(p.at("min_ms").get<double>(), p.at("max_ms").get<double>()) << pass;
    }
    EXPECT_GT(run.at("total").at("wall_median_ms").get<double>(), 0.0);
    EXPECT_TRUE(run.at("times_the_copy").contains("filter H"));
  }
  const nlohmann::json sat = bench_json(
      "--frames 1 --warmup 0 --technique msm --filter sat --width 32 --height 32 "
      "--shadow-map-size 128",
      "bench-sat.json");
  ASSERT_TRUE(sat.contains("runs"));
  EXPECT_TRUE(sat.at("runs").at(0).at("passes").contains("SAT rows"));
  EXPECT_TRUE(sat.at("runs").at(0).at("passes").contains("SAT columns"));
}

// PCSS's and backprojection's texel reads per pixel (a texelFetch, gather
// or compare each), counted in a variant of the lighting pass: PCSS reads
// at most its two blocker searches' samples and its filter's taps;
// techniques whose reads do not vary per pixel are not counted. Through
// virtual maps every texel is two reads, its page table's entry and the
// pool's texel, so a gather or a compare is eight, and finding the
// resident level reads an entry a level.
TEST(Cli, BenchCountsTheSoftShadowLookupsTexelReads) {
  const std::string options =
      "--frames 1 --warmup 0 --technique hard,pcss,backprojection --light spot --light-size 1.5 "
      "--pcss-blocker-samples 8 --pcss-filter-samples 16 --width 64 --height 36 "
      "--shadow-map-size 256";
  const nlohmann::json j = bench_json(options, "bench-fetches.json");
  const nlohmann::json virtual_maps =
      bench_json(options + " --shadow-maps virtual", "bench-virtual-fetches.json");
  for (const nlohmann::json* bench : {&j, &virtual_maps}) {
    ASSERT_EQ(bench->at("runs").size(), 3u);
    EXPECT_FALSE(bench->at("runs").at(0).contains("fetches_per_pixel"));
    for (int run : {1, 2}) {
      const auto& fetches = bench->at("runs").at(run).at("fetches_per_pixel");
      EXPECT_GT(fetches.at("mean").get<double>(), 0.0);
      EXPECT_LE(fetches.at("min").get<double>(), fetches.at("mean").get<double>());
      EXPECT_LE(fetches.at("mean").get<double>(), fetches.at("max").get<double>());
    }
  }
  const auto& pcss = j.at("runs").at(1).at("fetches_per_pixel");
  const auto& virtual_pcss = virtual_maps.at("runs").at(1).at("fetches_per_pixel");
  EXPECT_LE(pcss.at("max").get<double>(), 2 * 8 + 16);
  EXPECT_LE(virtual_pcss.at("max").get<double>(), 8 * (2 * 8 + 16) + penumbra::kMaxVirtualLevels);
  EXPECT_GT(virtual_pcss.at("mean").get<double>(), pcss.at("mean").get<double>());
}

// --technique none is the frame without shadows: it has no maps, so no
// pass over them and no yardstick copying them.
TEST(Cli, BenchTimesAFrameWithoutShadows) {
  const nlohmann::json j = bench_json(
      "--frames 1 --warmup 0 --technique none,hard --width 32 --height 32 --shadow-map-size 128",
      "bench-none.json");
  ASSERT_TRUE(j.contains("runs"));
  ASSERT_EQ(j.at("runs").size(), 2u);
  const auto& none = j.at("runs").at(0).at("passes");
  EXPECT_TRUE(none.contains("lighting"));
  EXPECT_FALSE(none.contains("shadow depth"));
  EXPECT_FALSE(none.contains("copy (yardstick)"));
  EXPECT_TRUE(j.at("runs").at(1).at("passes").contains("copy (yardstick)"));
}

// Cached shadow maps in the same run: a frame drawing every view, a static
// frame (no view drawn) and one where an object moved (the views that see
// it drawn), their times in the JSON.
TEST(Cli, BenchMeasuresCachedShadowMaps) {
  const std::string json_path = out_path("bench-cached.json");
  const Result r =
      run("bench --frames 2 --warmup 0 --technique hard,vsm --width 64 --height 48 "
          "--shadow-map-size 256 --json " +
          json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("static frame"), std::string::npos) << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j.at("runs").size(), 2u);
  for (const auto& run : j.at("runs")) {
    const auto& cached = run.at("cached_shadow_maps");
    EXPECT_EQ(cached.at("views").get<int>(), 4);  // the spot light and three cascades
    EXPECT_EQ(cached.at("static_views_drawn").get<int>(), 0);
    EXPECT_GE(cached.at("moving_views_drawn").get<int>(), 1);
    EXPECT_EQ(cached.at("moving_shape").get<int>(), 1);  // the box: shape 0 is the ground
    for (const char* frame : {"full", "static", "moving"}) {
      EXPECT_GE(cached.at(frame).at("wall_median_ms").get<double>(), 0.0) << frame;
    }
  }
}

// --fused on (the default) replaces the resolve and both blur passes with
// one, up to W = 16; past it the two-pass path runs, and the JSON says which.
TEST(Cli, BenchReportsTheFusedFilterAndItsFallback) {
  const std::string json_path = out_path("bench-fused.json");
  Result r =
      run("bench --frames 1 --warmup 0 --technique msm16 --filter gaussian --sweep blur "
          "--width 32 --height 24 --shadow-map-size 64 --json " +
          json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("msm16 gaussian W=4 fused (RGBA16)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("msm16 gaussian W=32 two-pass (RGBA16)"), std::string::npos) << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  int fused_runs = 0;
  for (const auto& run : j.at("runs")) {
    const int blur = run.at("blur").get<int>();
    const auto& passes = run.at("passes");
    const bool fused = blur >= 1 && blur <= 16;
    EXPECT_EQ(run.at("fused").get<bool>(), fused) << blur;
    EXPECT_EQ(passes.contains("resolve+filter (fused)"), fused) << blur;
    EXPECT_EQ(passes.contains("resolve"), !fused) << blur;
    EXPECT_EQ(passes.contains("filter H"), blur > 16) << blur;
    EXPECT_EQ(run.at("representation_format").get<std::string>(), "RGBA16");
    fused_runs += fused ? 1 : 0;
  }
  EXPECT_EQ(fused_runs, 5);  // W = 1, 2, 4, 8, 16
  // Its bytes per texel at W = 4: the depth under each 32 x 32 tile and its
  // apron, (40 / 32)^2 x 4, and the RGBA16 moments written once: 14.25.
  for (const auto& run : j.at("runs")) {
    if (run.at("blur").get<int>() != 4) continue;
    const auto& fused = run.at("bytes_per_texel").at("resolve+filter (fused)");
    EXPECT_LE(fused.at("total").get<double>(), 16.0);
    EXPECT_EQ(fused.at("written").get<double>(), 8.0);
  }

  // --sweep fused measures both paths in one run, fused first.
  r =
      run("bench --frames 1 --warmup 0 --technique evsm4 --blur 4 --sweep fused "
          "--width 32 --height 24 --shadow-map-size 64 --json " +
          json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream again(json_path);
  const nlohmann::json sweep = nlohmann::json::parse(again);
  ASSERT_EQ(sweep.at("runs").size(), 2u);
  EXPECT_TRUE(sweep.at("runs").at(0).at("fused").get<bool>());
  EXPECT_TRUE(sweep.at("runs").at(0).at("passes").contains("resolve+filter (fused)"));
  EXPECT_FALSE(sweep.at("runs").at(1).at("fused").get<bool>());
  EXPECT_TRUE(sweep.at("runs").at(1).at("passes").contains("filter V"));
  EXPECT_EQ(sweep.at("runs").at(1).at("representation_format").get<std::string>(), "RGBA32F");
}

// bench --accumulate N times one sub-frame per frame (its shadow maps from
// another point of the source, and the sum's accumulate pass) and reports
// what the N sub-frames of a converged image cost: the camera's passes
// (G-buffer, ambient occlusion) once, as the renderer reuses them, the
// rest N times.
TEST(Cli, BenchTimesAccumulatedSubframes) {
  const std::string json_path = out_path("bench-accumulate.json");
  Result r =
      run("bench --frames 2 --warmup 0 --technique hard --accumulate 8 --width 32 --height 24 "
          "--shadow-map-size 64 --json " +
          json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("a converged image (8 sub-frames, the camera's passes once)"),
            std::string::npos)
      << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& run = j.at("runs").at(0);
  EXPECT_EQ(run.at("accumulate").get<int>(), 8);
  EXPECT_TRUE(run.at("passes").contains("accumulate"));
  EXPECT_TRUE(run.at("passes").contains("shadow depth"));
  const auto wall = [&](const char* pass) {
    return run.at("passes").at(pass).at("wall_median_ms").get<double>();
  };
  const double camera = wall("G-buffer") + wall("SSAO");
  EXPECT_GT(camera, 0.0);
  EXPECT_NEAR(run.at("converged_image_wall_ms").get<double>(),
              camera + 8.0 * (run.at("total").at("wall_median_ms").get<double>() - camera), 1e-9);
}

// Each pass over the shadow maps reports its bytes per texel (as its
// formats give them: msm's resolve writes RGBA32F, a W = 2 Gaussian pass
// over a 256^2 map reads 16 (1 + 4 / 64) bytes), the bandwidth it
// achieved, and with --bandwidth its floor: its bytes at that rate.
TEST(Cli, BenchCountsBytesPerTexel) {
  const std::string json_path = out_path("bench-bytes.json");
  Result r =
      run("bench --frames 1 --warmup 0 --technique msm --filter gaussian --blur 2 "
          "--no-fused --width 48 --height 32 --shadow-map-size 256 --bandwidth 500 --json " +
          json_path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("floor at 500 GB/s (--bandwidth)"), std::string::npos) << r.out;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("bandwidth_gb_per_second").get<double>(), 500.0);
  const auto& run = j.at("runs").at(0);
  const auto& bytes = run.at("bytes_per_texel");
  EXPECT_EQ(bytes.at("resolve").at("read").get<double>(), 4.0);
  EXPECT_EQ(bytes.at("resolve").at("written").get<double>(), 16.0);
  for (const char* pass : {"filter H", "filter V"}) {
    EXPECT_DOUBLE_EQ(bytes.at(pass).at("read").get<double>(), 16.0 * (1.0 + 4.0 / 64.0)) << pass;
    EXPECT_EQ(bytes.at(pass).at("written").get<double>(), 16.0) << pass;
  }
  EXPECT_EQ(bytes.at("copy (yardstick)").at("total").get<double>(), 32.0);
  EXPECT_FALSE(bytes.contains("shadow depth")) << "rasterized: not a per-texel count";
  const double texels = run.at("texels").get<double>();
  EXPECT_EQ(static_cast<long>(texels) % (256 * 256), 0) << "whole layers of the map";
  for (const auto& [pass, b] : bytes.items()) {
    EXPECT_GT(run.at("gb_per_second").at(pass).get<double>(), 0.0) << pass;
    EXPECT_DOUBLE_EQ(run.at("floor_ms").at(pass).get<double>(),
                     b.at("total").get<double>() * texels / 500e6)
        << pass;
  }
}

TEST(Cli, BenchUsageErrors) {
  const std::string json_path = out_path("bench-bad.json");
  expect_error("bench --technique msm,blurry", 2, "blurry", json_path, "--json");
  expect_error("bench --sweep sideways", 2, "--sweep", json_path, "--json");
  expect_error("bench --frames 0", 2, "--frames", json_path, "--json");
  expect_error("bench --bandwidth 0", 2, "--bandwidth", json_path, "--json");
  expect_error("bench", 2, "does not exist", "/no/such/folder/b.json", "--json");
}

TEST(Cli, RendersEveryTechnique) {
  for (const char* technique : {"none", "hard", "pcf", "pcss"}) {
    const std::string png = out_path(std::string(technique) + ".png");
    Result r = run(std::string("render --width 48 --height 32 --shadow-map-size 128 --technique ") +
                   technique + " -o " + png);
    EXPECT_EQ(r.status, 0) << technique << ": " << r.err;
    EXPECT_TRUE(fs::exists(png)) << technique;
  }
  const std::string soft = out_path("soft.png");
  Result r =
      run("render --width 48 --height 32 --shadow-map-size 128 --technique msm --filter sat "
          "--soft -o " +
          soft);
  EXPECT_EQ(r.status, 0) << r.err;
}

// One line on stdout names the file written, its size, view and
// technique (as the command line spelled it or not); --quiet prints nothing.
TEST(Cli, RenderSaysWhatItWroteUnlessQuiet) {
  const std::string png = out_path("said.png");
  const Result r =
      run("render --width 48 --height 32 --shadow-map-size 128 --technique PCSS -o " + png);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  EXPECT_EQ(r.out, "wrote " + png + " (48x32, final, technique pcss)\n");
  EXPECT_EQ(r.err, "");
  const std::string quiet_png = out_path("quiet.png");
  const Result quiet =
      run("render --width 48 --height 32 --shadow-map-size 128 --quiet -o " + quiet_png);
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_TRUE(fs::exists(quiet_png));
  EXPECT_EQ(quiet.out, "");
}

// With its output in a file (no terminal), bench says up front how long it
// expects to take, then one line on stderr as each configuration starts.
TEST(Cli, BenchEstimatesAndReportsProgressOffATerminal) {
  const Result r =
      run("bench --technique HARD,pcf,vsm --frames 2 --warmup 1 --width 32 --height 24 "
          "--shadow-map-size 64");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::regex estimate(
      "estimate: about [0-9.]+ s for 3 configurations of 3 frames \\(1 warm-up\\)");
  EXPECT_TRUE(std::regex_search(r.out, estimate)) << r.out;
  // The estimate comes before the first result.
  EXPECT_LT(r.out.find("estimate:"), r.out.find("\nhard")) << r.out;
  std::size_t at = 0;
  int index = 0;
  for (const char* technique : {"hard", "pcf", "vsm"}) {
    const std::string line = std::string("bench: ") + technique;
    const std::size_t found = r.err.find(line, at);
    ASSERT_NE(found, std::string::npos) << line << "\n" << r.err;
    std::string done = "(";
    done += std::to_string(index);
    done += " of 3 items done";
    EXPECT_NE(r.err.find(done, found), std::string::npos) << r.err;
    at = found + line.size();
    ++index;
  }
}

TEST(Cli, RendersEveryFilteredTechnique) {
  for (const char* technique : {"vsm", "esm", "msm", "msm16", "evsm2", "evsm4"}) {
    for (const char* filter : {"gaussian", "sat"}) {
      const std::string t = technique;
      const bool exponential = t == "esm" || t == "evsm2" || t == "evsm4";
      if (exponential && std::string(filter) == "sat") continue;  // refused (UsageErrors)
      const std::string png = out_path(std::string(technique) + "-" + filter + ".png");
      Result r = run(std::string("render --width 48 --height 32 --shadow-map-size 128 --blur 3 ") +
                     "--technique " + technique + " --filter " + filter + " -o " + png);
      EXPECT_EQ(r.status, 0) << technique << " " << filter << ": " << r.err;
      EXPECT_TRUE(fs::exists(png)) << technique << " " << filter;
    }
  }
}

TEST(Cli, SsaoUsageErrors) {
  const std::string out = out_path("ssao.png");
  expect_error("render --ssao maybe", 2, "--ssao", out);
  expect_error("render --ssao 1", 2, "--ssao", out);
  expect_error("render --ssao-half-resolution yes", 2, "--ssao-half-resolution", out);
  expect_error("render --ssao-samples 0", 2, "--ssao-samples", out);
  expect_error("render --ssao-samples 65", 2, "--ssao-samples", out);
  expect_error("render --ssao-samples 8.5", 2, "--ssao-samples", out);
  expect_error("render --ssao-radius 0", 2, "--ssao-radius", out);
  expect_error("render --ssao-radius nan", 2, "--ssao-radius", out);
  expect_error("render --ssao-bias -0.1", 2, "--ssao-bias", out);
  expect_error("render --ssao-range inf", 2, "--ssao-range", out);
  expect_error("render --ssao-blur 17", 2, "--ssao-blur", out);
  expect_error("render --ssao off --view ao", 2, "--view ao", out);
}

TEST(Cli, RendersTheAoView) {
  for (const char* half : {"off", "on"}) {
    for (const char* extension : {".png", ".exr"}) {
      const std::string path = out_path(std::string("ao-half-") + half + extension);
      Result r = run(std::string("render --width 48 --height 32 --view ao --ssao-samples 8 ") +
                     "--ssao-half-resolution " + half + " -o " + path);
      EXPECT_EQ(r.status, 0) << half << " " << extension << ": " << r.err;
      EXPECT_TRUE(fs::exists(path)) << path;
    }
  }
  const std::string off = out_path("ssao-off.png");
  Result r = run("render --width 48 --height 32 --ssao off -o " + off);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(off));
}

TEST(Cli, ShadowMapAboveTheGpuLimitIsRefused) {
  // Within the option's range but above what llvmpipe (16384) and most
  // GPUs allow.
  const std::string out = out_path("huge.png");
  expect_error("render --shadow-map-size 32768 --width 8 --height 8", 2, "exceeds this GPU's limit",
               out);
}

TEST(Cli, BadOutputPaths) {
  expect_error("render --width 8 --height 8", 2, "does not exist",
               (fs::path(PENUMBRA_TEST_OUTPUT) / "no-such-folder" / "x.png").string());
  expect_error("render --width 8 --height 8", 2, ".png or .exr", out_path("image.jpg"));
  // procfs refuses new files even to root.
  expect_error("render --width 8 --height 8", 2, "not writable", "/proc/self/x.png");
  const fs::path locked = fs::path(PENUMBRA_TEST_OUTPUT) / "cli" / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  if (access(locked.c_str(), W_OK) != 0) {  // root may write anyway
    expect_error("render --width 8 --height 8", 2, "not writable", (locked / "x.png").string());
  }
  fs::permissions(locked, fs::perms::owner_all);
  // A folder that claims to be writable but refuses the file: the failure
  // comes at write time (status 1) and still leaves nothing behind.
  if (access("/sys", W_OK) == 0) {
    expect_error("render --width 8 --height 8", 1, "cannot write '/sys/x.png'", "/sys/x.png");
  }
}

TEST(Cli, BadSceneFiles) {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "cli";
  fs::create_directories(dir);
  const std::string out = out_path("scene.png");
  expect_error("render --scene " + (dir / "missing.json").string(), 1, "missing.json", out);
  { std::ofstream(dir / "truncated.json") << R"({"lights": [{"type": "spot"}], "obj)"; }
  expect_error("render --scene " + (dir / "truncated.json").string(), 1, "truncated.json", out);
  {
    std::ofstream(dir / "badkey.json")
        << R"({"lights": [{"type": "spot"}], "objects": [{"shape": "box", "szie": [1,1,1]}]})";
  }
  expect_error("render --scene " + (dir / "badkey.json").string(), 1, "/objects/0/szie", out);
}

TEST(Cli, LightTypeUsageErrors) {
  const std::string out = out_path("lights.png");
  expect_error("render --light lamp", 2, "lamp", out);
  expect_error("render --cascades 0", 2, "--cascades", out);
  expect_error("render --cascades 5", 2, "--cascades", out);
  expect_error("render --cascade-lambda 1.5", 2, "--cascade-lambda", out);
  expect_error("render --cascade-blend -0.1", 2, "--cascade-blend", out);
  expect_error("render --guard-band maybe", 2, "--guard-band", out);
  expect_error("render --light point --light-direction 0,-1,0", 2, "--light-direction", out);
  expect_error("render --light directional --light-position 0,1,0", 2, "--light-position", out);
  expect_error("render --light point --view shadow --light-index 1", 2, "--light-index", out);
}

TEST(Cli, RendersEveryLightType) {
  for (const char* light : {"spot", "directional", "point"}) {
    for (const char* view : {"final", "shadow-map", "cascades", "texel-density"}) {
      const std::string png = out_path(std::string(light) + "-" + view + ".png");
      Result r = run(std::string("render --width 48 --height 32 --shadow-map-size 64 --light ") +
                     light + " --view " + view + " --guard-band off --cascades 2 -o " + png);
      EXPECT_EQ(r.status, 0) << light << " " << view << ": " << r.err;
      EXPECT_TRUE(fs::exists(png)) << light << " " << view;
      // The texel-density view also says how many pixels get a texel.
      EXPECT_EQ(r.out.find("texel density") != std::string::npos,
                std::string(view) == "texel-density")
          << r.out;
    }
  }
}

TEST(Cli, HelpListsEveryOptionWithItsDefault) {
  Result r = run("render --help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--scene",         "--technique",   "--view",
                             "--width",         "--height",      "--shadow-map-size",
                             "--constant-bias", "--slope-bias",  "--normal-offset",
                             "--light-size",    "--output",      "--ssao",
                             "--ssao-samples",  "--ssao-radius", "--ssao-bias",
                             "--ssao-range",    "--ssao-blur",   "--ssao-half-resolution",
                             "--light",         "--cascades",    "--cascade-lambda",
                             "--cascade-blend", "--guard-band",  "--contact-shadows"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option << " missing from --help";
  }
  EXPECT_NE(r.out.find("2048"), std::string::npos) << "shadow-map-size default not shown";
}

// Each command's --help shows the default it runs: bench measures msm
// unless told otherwise (its help used to say hard).
TEST(Cli, HelpShowsTheTechniqueEachCommandRuns) {
  for (const auto& [command, shown] :
       {std::pair{"render", "evsm4; default: hard]"}, std::pair{"bench", "evsm4; default: msm]"}}) {
    Result r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0);
    // Descriptions are wrapped: read them as one line.
    const std::string text = std::regex_replace(r.out, std::regex("\n +"), " ");
    EXPECT_NE(text.find(shown), std::string::npos) << command << ": " << shown;
  }
}

TEST(Cli, NoCommandIsAUsageError) {
  Result r = run("");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
}

TEST(Cli, RendersPngAndExr) {
  const std::string png = out_path("ok.png");
  Result r = run("render --width 64 --height 48 --shadow-map-size 256 -o " + png);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(png));
  const std::string exr = out_path("ok.exr");
  r = run("render --width 64 --height 48 --shadow-map-size 256 --view shadow -o " + exr);
  EXPECT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(exr));
  // 64 x 48 RGBA floats, compressed, but certainly more than a header.
  EXPECT_GT(fs::file_size(exr), 200u);
  std::ifstream in(exr, std::ios::binary);
  unsigned char magic[4] = {};
  in.read(reinterpret_cast<char*>(magic), 4);
  EXPECT_EQ(magic[0], 0x76);  // OpenEXR magic number 20000630
  EXPECT_EQ(magic[1], 0x2f);
  EXPECT_EQ(magic[2], 0x31);
  EXPECT_EQ(magic[3], 0x01);
}

}  // namespace
