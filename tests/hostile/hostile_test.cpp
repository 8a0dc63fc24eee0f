// The binary against hostile input and failures, one test per kind found:
// no hang, no crash, no truncated file published, no orphaned reader, no
// corrupted cache trusted, and one clear error line. Commands that could
// hang run under `timeout`, so that a regression fails rather than stalls.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <tuple>

#include "gltf_files.hpp"
#include "hostile/hostile_run.hpp"
#include "model_files.hpp"

namespace penumbra::hostile {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// Small renders: llvmpipe on a few shared cores.
const std::string kSmall = " --width 32 --height 24 --shadow-map-size 256";

// Waits up to `limit` for `done`, polling; true if it came.
template <class Done>
bool eventually(Done done, std::chrono::milliseconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(20ms);
  }
  return done();
}

// Whether a command writing into `dir` has staged files there yet: a
// folder in it (its hidden staging folder) that is not empty.
bool holds_staged_files(const std::string& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory() && !fs::is_empty(entry.path())) return true;
  }
  return false;
}

// The one cache entry a compare run left in `cache`.
std::string cache_entry(const std::string& cache) {
  std::string found;
  for (const auto& entry : fs::directory_iterator(cache)) {
    if (entry.path().filename().string().rfind("reference-", 0) == 0) found = entry.path().string();
  }
  return found;
}

// 1. A scene path that is a device is refused before anything is read.
TEST(Hostile, SceneDevicesAreRefusedUnread) {
  for (const std::string device : {"/dev/urandom", "/dev/zero"}) {
    const Result r = shell("timeout 20 PENUMBRA render --scene " + device + " -o x.png");
    EXPECT_EQ(r.status, 1) << device << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, "is not a regular file")) << r.err;
  }
  // A regular file above the limit is refused unread too (sparse: no disk).
  const std::string big = fresh_dir("scene_size") + "/big.json";
  std::ofstream(big).close();
  fs::resize_file(big, (16u << 20) + 1);
  const Result r = shell("timeout 20 PENUMBRA render --scene " + big + " -o x.png");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "larger than the limit of 16 MiB")) << r.err;
}

// 2. A FIFO as the scene file does not block.
TEST(Hostile, SceneFifoIsRefused) {
  const std::string fifo = fresh_dir("scene_fifo") + "/scene.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const Result r = shell("timeout 20 PENUMBRA render --scene " + fifo + " -o x.png");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "is not a regular file")) << r.err;
}

// 3. A FIFO in place of a cache entry does not block compare; the entry is
// replaced by the traced reference.
TEST(Hostile, CacheFifoDoesNotBlock) {
  const std::string dir = fresh_dir("cache_fifo");
  const std::string compare =
      "timeout 60 PENUMBRA compare --techniques hard" + kSmall + " --cache-dir " + dir;
  ASSERT_EQ(shell(compare).status, 0);
  const std::string entry = cache_entry(dir);
  ASSERT_FALSE(entry.empty());
  fs::remove(entry);
  ASSERT_EQ(mkfifo(entry.c_str(), 0600), 0);
  const Result r = shell(compare);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(entry)) << "the FIFO was not replaced";
  EXPECT_EQ(shell(compare).out.find(", cached;") != std::string::npos, true) << "not reused";
}

// 4. A view too large for memory ends in one error line, promptly. (Where
// the GPU has the memory, as a large discrete one may, the image is
// written instead; the address-space limit may also stop its driver at the
// start, which is the same one line.)
void expect_image_or_one_line(const Result& r, const std::string& out) {
  if (r.status == 0) {
    EXPECT_TRUE(out.empty() || fs::is_regular_file(out));
    return;
  }
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "penumbra: error: ")) << r.err;
  EXPECT_TRUE(r.err.find("out of") != std::string::npos ||
              r.err.find("ulimit -v") != std::string::npos)
      << r.err;
  if (!out.empty()) {
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(Hostile, OutOfGpuMemoryIsOneLine) {
  const std::string out = fresh_dir("huge") + "/huge.png";
  const Result r = shell(
      "ulimit -v 3000000; timeout 120 PENUMBRA render --width 16384 "
      "--height 16384 --shadow-map-size 256 -o " +
      out);
  expect_image_or_one_line(r, out);
  // The viewer too, in a window on an X server of its own where there is
  // one (-displayfd: the server picks a free display and writes it).
  if (shell("command -v Xvfb").status != 0) {
    GTEST_SKIP() << "Xvfb is not installed (Debian package xvfb): view not tried";
  }
  const std::string display = fresh_dir("huge_view") + "/display";
  const Result view =
      shell("Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>" + display +
            " 2>/dev/null & x=$!; for i in $(seq 200); do [ -s " + display +
            " ] && break; sleep 0.05; done; DISPLAY=:$(cat " + display +
            ") sh -c 'ulimit -v 3000000; exec timeout 120 PENUMBRA view --frames 3 --width 16384 "
            "--height 16384 --shadow-map-size 256'; s=$?; kill $x; wait $x; exit $s");
  expect_image_or_one_line(view, "");
}

// 5. The model reader dies with penumbra (an OBJ whose material library is
// a FIFO blocks assimp's reader).
TEST(Hostile, ModelReaderDiesWithItsParent) {
  const std::string dir = fresh_dir("reader_orphan");
  ASSERT_EQ(mkfifo((dir + "/blocks.mtl").c_str(), 0600), 0);
  write_text(dir + "/model.obj", "mtllib blocks.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const int signal : {SIGKILL, SIGTERM}) {
    const pid_t penumbra = spawn({"render", "--model", dir + "/model.obj", "-o", dir + "/m.png"});
    std::vector<pid_t> readers;
    ASSERT_TRUE(eventually([&] { return !(readers = children_of(penumbra)).empty(); }, 10s));
    kill(penumbra, signal);
    waitpid(penumbra, nullptr, 0);
    // The reader would otherwise wait on the FIFO for ever: nothing is
    // left to stop it.
    EXPECT_TRUE(eventually([&] { return !running(readers.front()); }, 5s))
        << "the model reader outlived penumbra (signal " << signal << ")";
    kill(readers.front(), SIGKILL);
  }
}

// 6. The reader's memory is capped: an OFF header promising 150 million
// faces ends in an out-of-memory error, not gigabytes taken.
TEST(Hostile, ModelReaderMemoryIsCapped) {
  const std::string dir = fresh_dir("reader_memory");
  write_text(dir + "/faces.off", "OFF\n3 150000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const Result r =
      shell("timeout 60 PENUMBRA render --model " + dir + "/faces.off -o " + dir + "/m.png");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "ran out of memory (its limit is 2048 MiB)")) << r.err;
}

// 7. Geometry beyond the budget is a usage error naming the numbers, before
// any of it reaches the driver.
TEST(Hostile, GeometryBudgetHolds) {
  const std::string dir = fresh_dir("geometry");
  std::string objects = "{\"shape\": \"plane\"}";
  for (int i = 0; i < 100; ++i) {
    objects += ", {\"shape\": \"sphere\", \"position\": [" + std::to_string(i % 10) + ", 1, " +
               std::to_string(i / 10) + "]}";
  }
  write_text(dir + "/spheres.json",
             "{\"lights\": [{\"type\": \"directional\"}], \"objects\": [" + objects + "]}");
  const Result r = shell("PENUMBRA_GEOMETRY_BUDGET=1 timeout 60 PENUMBRA render --scene " + dir +
                         "/spheres.json" + kSmall + " -o " + dir + "/s.png");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "exceeds the budget of 1 MiB at object")) << r.err;
  EXPECT_NE(r.err.find("PENUMBRA_GEOMETRY_BUDGET"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/s.png"));
}

// 8. A write that fails (a file-size limit, as a full disk) is an error and
// publishes nothing: neither a truncated image nor zero-byte ones.
TEST(Hostile, FailedWritesPublishNothing) {
  const std::string dir = fresh_dir("full");
  // ulimit -f 1: 512 bytes, enough for the error line on stderr (a file
  // here), less than any of the images.
  const Result r =
      shell("ulimit -f 1; timeout 60 PENUMBRA render" + kSmall + " -o " + dir + "/r.png");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, "File too large")) << r.err;
  const Result c = shell(
      "ulimit -f 1; timeout 60 PENUMBRA compare --techniques hard --no-cache --width 200 "
      "--height 150 --shadow-map-size 256 -o " +
      dir + "/c");
  EXPECT_EQ(c.status, 1) << c.err;
  EXPECT_TRUE(one_error_line(c.err, "File too large")) << c.err;
  EXPECT_TRUE(fs::is_empty(dir)) << "output left in " << dir;
}

// 9. An output that is a link or a device is written through, never
// replaced; "-" is standard output.
TEST(Hostile, NonRegularOutputsAreWrittenInPlace) {
  const std::string dir = fresh_dir("in_place");
  fs::create_symlink("/dev/null", dir + "/null.png");
  fs::create_symlink(dir + "/target.json", dir + "/link.json");
  write_text(dir + "/target.json", "old");
  const std::string bench =
      "timeout 60 PENUMBRA bench --frames 1 --warmup 0 --technique hard" + kSmall + " --json ";
  ASSERT_EQ(shell("timeout 60 PENUMBRA render" + kSmall + " -o " + dir + "/null.png").status, 0);
  EXPECT_TRUE(fs::is_symlink(dir + "/null.png"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  ASSERT_EQ(shell(bench + dir + "/link.json").status, 0);
  EXPECT_TRUE(fs::is_symlink(dir + "/link.json")) << "the link was replaced";
  EXPECT_TRUE(nlohmann::json::accept(read_text(dir + "/target.json")));
  const Result r = shell("cd " + dir + " && " + bench + "-");
  ASSERT_NE(r.out.find("\n{"), std::string::npos) << r.out;
  EXPECT_TRUE(nlohmann::json::accept(r.out.substr(r.out.find("\n{") + 1))) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/-"));
}

// 10. A legal 255-byte file name is written (its temporary name is
// shortened to fit the limit).
TEST(Hostile, LongestFileNameIsWritten) {
  const std::string dir = fresh_dir("long_name");
  const std::string name = std::string(251, 'n') + ".png";
  const Result r = shell("timeout 60 PENUMBRA render" + kSmall + " -o " + dir + "/" + name);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir + "/" + name));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// 11. An interrupted report leaves neither a partial folder nor its
// temporary one, nor the folder of its shader rehearsal (on llvmpipe,
// report/shader_rehearsal.hpp) in TMPDIR.
TEST(Hostile, InterruptedFolderOutputLeavesNothing) {
  const std::string dir = fresh_dir("interrupted");
  const std::string tmp = fresh_dir("interrupted-tmp");
  const std::string report = dir + "/report";
  setenv("TMPDIR", tmp.c_str(), 1);
  const pid_t penumbra = spawn({"report", "--quick", "-o", report});
  unsetenv("TMPDIR");
  // Interrupted once it has written some images, while it rehearses.
  const auto under_way = [&] { return holds_staged_files(dir) && !fs::is_empty(tmp); };
  const bool started = eventually(under_way, 120s);
  kill(penumbra, SIGTERM);
  int status = 0;
  waitpid(penumbra, &status, 0);
  ASSERT_TRUE(started) << "the report wrote nothing, or rehearsed nothing, within 120 s";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_TRUE(fs::is_empty(dir)) << "left behind: " << fs::directory_iterator(dir)->path();
  EXPECT_TRUE(fs::is_empty(tmp)) << "left behind: " << fs::directory_iterator(tmp)->path();
}

// 11b. A crash (a failed assert inside a library raises SIGABRT; a driver
// may die of SIGSEGV, SIGBUS or SIGFPE) ends every long-running command
// with one "internal error" line, no staged folder or file left, and the
// signal itself as the exit status. The signal is sent from outside once
// the command is under way, as a crash would come.
TEST(Hostile, CrashSignalsEndInOneLineAndLeaveNothing) {
  struct Case {
    std::vector<std::string> args;  // "OUT" stands for the output path
    int signal;
    bool stages;  // whether it writes a staged folder to wait for
  };
  const std::vector<Case> cases = {
      {{"report", "--quick", "-o", "OUT"}, SIGABRT, true},
      {{"report", "--quick", "-o", "OUT"}, SIGSEGV, true},
      {{"report", "--quick", "-o", "OUT"}, SIGBUS, true},
      {{"report", "--quick", "-o", "OUT"}, SIGFPE, true},
      {{"compare", "--techniques", "hard,pcf,pcss,vsm,msm", "--width", "320", "--height", "180",
        "--no-cache", "-o", "OUT", "--json", "OUT.json"},
       SIGABRT,
       true},
      {{"bench", "--frames", "100000", "--width", "64", "--height", "36", "--json", "OUT.json"},
       SIGABRT,
       false},
  };
  for (const Case& c : cases) {
    const std::string dir = fresh_dir("crash");
    const std::string log = fresh_dir("crash_log") + "/stderr.txt";
    std::vector<std::string> args = c.args;
    for (std::string& a : args) {
      if (a.rfind("OUT", 0) == 0) a = dir + "/out" + a.substr(3);
    }
    const int err = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(err, 0);
    const pid_t penumbra = spawn(args, -1, err);
    close(err);
    const auto staged_files = [&] { return holds_staged_files(dir); };
    const bool started =
        c.stages ? eventually(staged_files, 120s) : (std::this_thread::sleep_for(3s), true);
    kill(penumbra, c.signal);
    int status = 0;
    waitpid(penumbra, &status, 0);
    const std::string what = args[0] + " with signal " + std::to_string(c.signal);
    ASSERT_TRUE(started) << what << ": wrote nothing within 120 s";
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == c.signal)
        << what << ": status " << status;
    EXPECT_TRUE(fs::is_empty(dir)) << what << " left " << fs::directory_iterator(dir)->path();
    // Progress lines may come first; the error is one line, the last.
    const std::string text = read_text(log);
    EXPECT_TRUE(
        ends_in_one_error_line(text, "internal error (signal " + std::to_string(c.signal) + ": "))
        << what << ":\n"
        << text;
    EXPECT_NE(text.find("please report it"), std::string::npos) << what << ":\n" << text;
  }
}

// 11c. Coordinates at the edges of float's range: decimals too small for
// a float read as zero (as assimp reads them), and finite coordinates near
// 3.4e38, in OBJ or PLY, are one error naming the file rather than a blank
// image.
TEST(Hostile, ModelCoordinatesAtTheEdgesOfFloat) {
  const std::string dir = fresh_dir("float_edges");
  const std::string tiny = dir + "/tiny.obj";
  write_text(tiny, "v 1e-50 0 0\nv 1 -2.5e-47 0\nv 0 1 1e-400\nf 1 2 3\n");
  const Result read =
      shell("timeout 60 PENUMBRA render --model " + tiny + kSmall + " -o " + dir + "/tiny.png");
  EXPECT_EQ(read.status, 0) << read.err;
  EXPECT_TRUE(fs::exists(dir + "/tiny.png"));

  const std::string huge_obj = dir + "/huge.obj";
  write_text(huge_obj, "v 0 0 0\nv 3.4e38 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string huge_ply = dir + "/huge.ply";
  write_text(huge_ply,
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n3.4e38 0 0\n0 3.4e38 0\n3 0 1 2\n");
  for (const std::string& model : {huge_obj, huge_ply}) {
    const Result r =
        shell("timeout 60 PENUMBRA render --model " + model + kSmall + " -o " + dir + "/huge.png");
    EXPECT_EQ(r.status, 1) << model << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, model + ": coordinates reach 3.4e+38")) << r.err;
    EXPECT_NE(r.err.find("too large to make a framed view"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/huge.png"));
  }
}

// 11c1. A glTF scene at its own scale with coordinates near 3.4e38: the
// camera, lights or ground made for it would overflow, so it is one error
// naming the file.
TEST(Hostile, GltfCoordinatesNearFloatsLimitAreOneError) {
  testing::GltfSpec spec;
  spec.materials.push_back({});
  spec.quads.push_back(
      {{{-3e38f, 0, 3e38f}, {3e38f, 0, 3e38f}, {3e38f, 1, -3e38f}, {-3e38f, 1, -3e38f}}});
  const std::string bare = testing::write_gltf("hostile-huge-coordinates.gltf", spec);
  // With its own camera and light, only the ground asked for is made.
  testing::GltfCameraSpec camera;
  camera.position = {0.0f, 10.0f, 10.0f};
  spec.cameras.push_back(camera);
  spec.lights.push_back({});
  const std::string lit = testing::write_gltf("hostile-huge-coordinates-lit.gltf", spec);
  const std::string dir = fresh_dir("gltf_huge");
  for (const auto& [path, extra, what] :
       {std::tuple<std::string, std::string, std::string>{bare, "", "a camera"},
        {lit, " --ground", "a ground"}}) {
    const Result r = shell("timeout 60 PENUMBRA render --scene " + path + extra + kSmall + " -o " +
                           dir + "/x.png");
    EXPECT_EQ(r.status, 1) << extra << "\n" << r.err;
    EXPECT_TRUE(ends_in_one_error_line(r.err, path + ": coordinates reach 3e+38")) << r.err;
    EXPECT_NE(r.err.find("too large to make " + what), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/x.png"));
  }
}

// 11c2. A PLY header line over the reader's 1 MiB limit (a huge comment)
// is said as such, not as a header without end_header.
TEST(Hostile, LongPlyHeaderLineIsSaid) {
  const std::string dir = fresh_dir("ply_comment");
  const std::string ply = dir + "/comment.ply";
  write_text(ply, "ply\nformat binary_little_endian 1.0\ncomment " +
                      std::string((1u << 20) + 10, 'c') +
                      "\nelement vertex 3\nproperty float x\nproperty float y\nproperty float "
                      "z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n");
  const Result r =
      shell("timeout 60 PENUMBRA render --model " + ply + kSmall + " -o " + dir + "/x.png");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(one_error_line(r.err, ply + ": header line 3 is longer than 1 MiB")) << r.err;
}

// 11d. A glTF camera glTF itself forbids (yfov <= 0, a negative
// aspectRatio) or whose field of view penumbra cannot show (under 1 or
// over 170 degrees) is one error naming the file, the camera and the
// value, not a blank image.
TEST(Hostile, DegenerateGltfCamerasAreErrors) {
  const std::string dir = fresh_dir("gltf_cameras");
  struct Case {
    float yfov, aspect_ratio;
    std::string culprit;
  };
  for (const Case& c : {Case{0.0f, 0.0f, "yfov 0 radians"}, Case{1e-6f, 0.0f, "yfov 1e-06"},
                        Case{-0.5f, 0.0f, "yfov -0.5"}, Case{3.2f, 0.0f, "yfov 3.2"},
                        Case{0.8f, -1.5f, "aspectRatio -1.5"}}) {
    testing::GltfSpec spec;
    spec.materials.push_back({});
    spec.quads.push_back({{{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}}});
    testing::GltfCameraSpec camera;
    camera.position = {0.0f, 2.0f, 3.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.yfov = c.yfov;
    camera.aspect_ratio = c.aspect_ratio;
    spec.cameras.push_back(camera);
    const std::string path = testing::write_gltf("hostile-camera.gltf", spec);
    const Result r =
        shell("timeout 60 PENUMBRA render --scene " + path + kSmall + " -o " + dir + "/camera.png");
    EXPECT_EQ(r.status, 1) << c.culprit << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, path + ": camera '")) << r.err;
    EXPECT_NE(r.err.find(c.culprit), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/camera.png"));
  }
}

// 11e. Whole numbers are decimal digits: hex (0x10), octal-looking (010
// is ten, not eight), exponents (1e3) and fractions are read or refused
// the same way for every integer option.
TEST(Hostile, WholeNumbersAreDecimal) {
  for (const std::string option : {"--accumulate", "--width", "--blur", "--camera-index"}) {
    for (const std::string value : {"0x10", "1e3", "5.0", "' 5'"}) {
      const Result r = shell("timeout 60 PENUMBRA render " + option + " " + value + " -o x.png");
      EXPECT_EQ(r.status, 2) << option << " " << value << "\n" << r.err;
      EXPECT_TRUE(one_error_line(r.err, option + ": ")) << r.err;
      EXPECT_NE(r.err.find("is not a whole number in decimal digits"), std::string::npos) << r.err;
    }
  }
  // 010 is ten: 10 sub-frames where CLI11 alone would run 8 (bench says).
  const Result bench = shell(
      "timeout 120 PENUMBRA bench --technique hard --accumulate 010 "
      "--frames 1 --warmup 0" +
      kSmall);
  EXPECT_EQ(bench.status, 0) << bench.err;
  EXPECT_NE(bench.out.find("10 sub-frames"), std::string::npos) << bench.out;
}

// 11e2. Textures penumbra will not decode: a PNG whose header claims more
// than 8192 texels a side, an image file of 8 GiB (sparse), a data: URI
// that is not base64. Each is one warning naming it, the material keeps
// its flat colour, and the scene draws.
TEST(Hostile, OversizedTexturesAreWarningsNotFailures) {
  // A PNG signature and an IHDR chunk of 11585 x 11585 RGBA: what
  // stb_image reads for the size (the pixels never come).
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0d", 4) + "IHDR";
  png += std::string("\0\0\x2d\x41\0\0\x2d\x41\x08\x06\0\0\0", 13);
  png += std::string("\0\0\0\0", 4);
  testing::write_model_file("hostile-huge-texture.png", png);
  const std::string sparse = testing::write_model_file("hostile-sparse-texture.png", "");
  fs::resize_file(sparse, std::uintmax_t{8} << 30);
  testing::GltfSpec spec;
  for (const std::string image :
       {"hostile-huge-texture.png", "hostile-sparse-texture.png", "data:image/png,notbase64"}) {
    testing::GltfMaterialSpec material;
    material.image = image;
    material.base_color = {0.5f, 0.6f, 0.7f, 1.0f};
    spec.materials.push_back(material);
  }
  for (int q = 0; q < 3; ++q) {
    const float x = static_cast<float>(q) * 2.0f;
    spec.quads.push_back({{{x - 1, 0, 1}, {x + 1, 0, 1}, {x + 1, 0, -1}, {x - 1, 0, -1}}, q});
  }
  const std::string path = testing::write_gltf("hostile-textures.gltf", spec);
  const std::string dir = fresh_dir("textures");
  const Result r = shell("timeout 120 PENUMBRA render --scene " + path + kSmall + " -o " + dir +
                         "/textures.png");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/textures.png"));
  for (const std::string said :
       {"11585x11585 is larger than 8192 texels a side; using the material's flat colour",
        "hostile-sparse-texture.png: the file is larger than the 512 MiB",
        "data: URI that is not base64"}) {
    EXPECT_NE(r.err.find(said), std::string::npos) << said << "\n" << r.err;
  }
  EXPECT_EQ(lines_starting_with(r.err, "penumbra: warning: "), 3) << r.err;
  fs::remove(sparse);
}

// 11e3. A glTF whose JSON is malformed, holds NaN or overflows a double,
// or a GLB without its JSON chunk: one error saying what is wrong, not
// assimp's "no suitable reader found".
TEST(Hostile, MalformedGltfIsSaidAsSuch) {
  const std::string dir = fresh_dir("malformed_gltf");
  struct Case {
    std::string name, content, said;
  };
  for (const Case& c : {Case{"cut.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [",
                             "not valid glTF JSON: parse error"},
                        Case{"nan.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"x\": NaN}",
                             "not valid glTF JSON: parse error"},
                        Case{"huge.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"x\": 1e400}",
                             "not valid glTF JSON: number overflow"},
                        Case{"bad.glb", std::string("glTF\x02\0\0\0\x20\0\0\0garbagegarbage", 26),
                             "the binary glTF has no JSON chunk"}}) {
    const std::string path = dir + "/" + c.name;
    write_text(path, c.content);
    for (const std::string how : {"--scene", "--model"}) {
      const Result r = shell("timeout 60 PENUMBRA render " + how + " " + path + kSmall + " -o " +
                             dir + "/x.png");
      EXPECT_EQ(r.status, 1) << c.name << "\n" << r.err;
      EXPECT_TRUE(one_error_line(r.err, path + ": " + c.said)) << r.err;
    }
  }
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

// 11f. A glTF with thousands of lights: the lights penumbra cannot draw
// are counted in one short warning, not listed by the thousand.
TEST(Hostile, ManyGltfLightsAreOneShortWarning) {
  testing::GltfSpec spec;
  spec.materials.push_back({});
  spec.quads.push_back({{{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}}});
  for (int i = 0; i < 2000; ++i) {
    testing::GltfLightSpec light;
    light.name = "light" + std::to_string(i);
    light.type = "point";
    light.position = {0.0f, 2.0f + 1e-4f * static_cast<float>(i), 0.0f};
    spec.lights.push_back(light);
  }
  const std::string path = testing::write_gltf("hostile-many-lights.gltf", spec);
  const std::string dir = fresh_dir("many_lights");
  const Result r =
      shell("timeout 120 PENUMBRA render --scene " + path + kSmall + " -o " + dir + "/lights.png");
  EXPECT_EQ(r.status, 0) << r.err.substr(0, 1000);
  EXPECT_LT(r.err.size(), 1000u) << r.err.substr(0, 1000);
  EXPECT_NE(r.err.find(" more"), std::string::npos) << r.err.substr(0, 1000);
  EXPECT_EQ(lines_starting_with(r.err, "penumbra: warning: "), 1) << r.err.substr(0, 1000);
}

// 12. Empty values are usage errors, not "not given".
TEST(Hostile, EmptyValuesAreUsageErrors) {
  const std::string dir = fresh_dir("empty");
  for (const std::string args :
       {"render --model '' -o x.png", "render --light '' -o x.png",
        "render --camera-position '' -o x.png", "render --camera-fov '' -o x.png", "render -o ''",
        "compare -o ''", "compare --json ''", "report -o ''"}) {
    const Result r = shell("cd " + dir + " && timeout 60 PENUMBRA " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, "empty")) << args << "\n" << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

// 13. Degenerate cameras and light directions are refused as a scene file
// refuses them; --light-index must name a light, whatever the view.
TEST(Hostile, DegenerateCamerasAndLightsAreUsageErrors) {
  for (const std::string args : {"--camera-position 0,10,0 --camera-target 0,0,0",
                                 "--camera-position 1,2,3 --camera-target 1,2,3",
                                 "--camera-position 0,0,0 --camera-target 1e-30,0,1e-30",
                                 "--light-direction 0,-1e-25,0", "--light-index 3"}) {
    const Result r = shell("timeout 60 PENUMBRA render " + args + " -o x.png");
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, args.substr(0, args.find(' ')))) << args << "\n" << r.err;
  }
}

// 14. Standard output is checked: a full device or a closed pipe is an
// error (status 1), not success or death by SIGPIPE.
TEST(Hostile, StandardOutputErrorsAreReported) {
  const std::string bench =
      "timeout 60 PENUMBRA bench --frames 1 --warmup 0 --technique hard" + kSmall;
  const Result full = shell(bench + " > /dev/full");
  EXPECT_EQ(full.status, 1) << full.err;
  EXPECT_TRUE(ends_in_one_error_line(full.err, "standard output: No space left on device"))
      << full.err;
  const Result compare =
      shell("timeout 60 PENUMBRA compare --techniques hard --no-cache" + kSmall + " > /dev/full");
  EXPECT_EQ(compare.status, 1) << compare.err;
  EXPECT_TRUE(one_error_line(compare.err, "standard output")) << compare.err;

  // A reader that has gone: the pipe's read end closed before the run.
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  close(fds[0]);
  const pid_t pid = spawn({"bench", "--frames", "1", "--warmup", "0", "--technique", "hard",
                           "--width", "32", "--height", "24", "--shadow-map-size", "256"},
                          fds[1]);
  close(fds[1]);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
}

// 15. A cache entry whose data was damaged (same size) is not trusted: one
// warning, traced anew, the same numbers as before.
TEST(Hostile, DamagedCacheEntryIsRetraced) {
  const std::string dir = fresh_dir("cache_damage");
  const std::string compare = "timeout 60 PENUMBRA compare --techniques hard" + kSmall +
                              " --cache-dir " + dir + " --json -";
  const Result first = shell(compare);
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string entry = cache_entry(dir);
  std::string bytes = read_text(entry);
  ASSERT_GT(bytes.size(), 64u);
  std::fill(bytes.begin() + 64, bytes.end(), '\0');
  write_text(entry, bytes);
  const Result second = shell(compare);
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(std::count(second.err.begin(), second.err.end(), '\n'), 1) << second.err;
  EXPECT_NE(second.err.find("penumbra: warning: ignoring the cached reference"), std::string::npos)
      << second.err;
  auto mae = [](const std::string& out) {
    const nlohmann::json j = nlohmann::json::parse(out.substr(out.find("\n{") + 1));
    EXPECT_FALSE(j["reference"]["cached"].get<bool>());
    return j["results"][0]["traced"]["mae"].get<double>();
  };
  EXPECT_EQ(mae(second.out), mae(first.out));
}

// 16. Messages: names with control characters are printed escaped; a folder
// in the cache's way gets a reason, not "Success"; no driver chatter (the
// GL errors of a huge view are left out of its one line: test 4).
TEST(Hostile, MessagesAreOneCleanLine) {
  const Result name =
      shell("timeout 20 PENUMBRA render --scene \"$(printf 'bad\\n\\033[31m.json')\" -o x.png");
  EXPECT_EQ(name.status, 1);
  EXPECT_TRUE(one_error_line(name.err, "'bad\\n\\x1b[31m.json'")) << name.err;
  // The same name in front of a JSON path inside the file.
  const std::string named = fresh_dir("control_name");
  const Result path = shell("cd " + named +
                            " && f=\"$(printf 'bad\\nname.json')\" && echo "
                            "'{\"lights\": [{\"type\": \"nope\"}]}' > \"$f\" && timeout 20 "
                            "PENUMBRA render --scene \"$f\" -o x.png");
  EXPECT_EQ(path.status, 1) << path.err;
  EXPECT_TRUE(one_error_line(path.err, "bad\\nname.json: /lights/0/type: ")) << path.err;

  const std::string dir = fresh_dir("cache_folder");
  const std::string compare =
      "timeout 60 PENUMBRA compare --techniques hard" + kSmall + " --cache-dir " + dir;
  ASSERT_EQ(shell(compare).status, 0);
  const std::string entry = cache_entry(dir);
  fs::remove(entry);
  fs::create_directory(entry);
  const Result folder = shell(compare);
  EXPECT_EQ(folder.status, 0);
  EXPECT_EQ(std::count(folder.err.begin(), folder.err.end(), '\n'), 1) << folder.err;
  EXPECT_NE(folder.err.find("it is a folder"), std::string::npos) << folder.err;
  EXPECT_EQ(folder.err.find("Success"), std::string::npos) << folder.err;

  // A cache folder Mesa cannot make: no shader-cache chatter on stderr.
  const Result cache = shell("HOME=/proc XDG_CACHE_HOME=/proc/none timeout 60 PENUMBRA render" +
                             kSmall + " -o " + fresh_dir("no_cache_home") + "/x.png");
  EXPECT_EQ(cache.status, 0) << cache.err;
  EXPECT_TRUE(cache.err.empty()) << cache.err;

  // Too little memory for the driver to load: one line, no loader chatter.
  const Result egl = shell("ulimit -v 150000; timeout 60 PENUMBRA render" + kSmall + " -o x.png");
  EXPECT_EQ(egl.status, 1);
  EXPECT_TRUE(one_error_line(egl.err, "ulimit -v")) << egl.err;
}

}  // namespace
}  // namespace penumbra::hostile

namespace penumbra::hostile {
namespace {

// 16. --shadow-msaa takes 1, 2, 4 or 8, and no more samples than the GPU
// offers for a depth texture (llvmpipe: 4): each other value is one line
// naming the flag, and no image appears.
TEST(Hostile, ShadowMsaaValuesAreUsageErrors) {
  const std::string dir = fresh_dir("shadow_msaa");
  for (const std::string value : {"3", "0", "16", "-4", "2.5", "four"}) {
    const Result r = shell("cd " + dir + " && timeout 60 PENUMBRA render --shadow-msaa " + value +
                           kSmall + " -o x.png");
    EXPECT_EQ(r.status, 2) << value << "\n" << r.err;
    EXPECT_TRUE(one_error_line(r.err, "--shadow-msaa")) << value << "\n" << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
  // Beyond the device's limit: refused when the maps are made, before any
  // output (a GPU that offers 8 renders it).
  const Result many = shell("cd " + dir + " && timeout 60 PENUMBRA render --shadow-msaa 8 " +
                            "--technique vsm" + kSmall + " -o x.png");
  if (many.status != 0) {
    EXPECT_EQ(many.status, 2) << many.err;
    EXPECT_TRUE(one_error_line(many.err, "--shadow-msaa 8 exceeds this GPU's limit")) << many.err;
    EXPECT_TRUE(fs::is_empty(dir));
  }
}

}  // namespace
}  // namespace penumbra::hostile
