// `penumbra view` in a real window on an Xvfb server that the test starts
// itself (so it runs where there is no display): scripted frames, its
// screenshot against `penumbra render` of the same settings, and the
// whole window with its panel.
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "io/image.hpp"
#include "penumbra/gl/gpu_profiler.hpp"

namespace {

namespace fs = std::filesystem;
using penumbra::Image;

// An Xvfb server on a display number it chooses itself (-displayfd), so
// parallel tests never race for one.
class XvfbServer {
 public:
  // `screen`: the screen's width x height x depth.
  explicit XvfbServer(const std::string& screen = "1280x1024x24") {
    int fds[2];
    if (pipe(fds) != 0) {
      error_ = "pipe failed";
      return;
    }
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten",
             "tcp", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    pollfd p{fds[0], POLLIN, 0};
    char c = 0;
    while (poll(&p, 1, 20000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (number.empty()) {
      error_ = "could not start Xvfb (install it with scripts/install-deps; Debian package xvfb)";
      return;
    }
    display_ = ":" + number;
  }
  ~XvfbServer() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  XvfbServer(const XvfbServer&) = delete;
  XvfbServer& operator=(const XvfbServer&) = delete;

  [[nodiscard]] const std::string& display() const { return display_; }
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
  std::string error_;
};

struct Result {
  int status = -1;
  std::string err;
};

fs::path output_dir() {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "view";
  fs::create_directories(dir);
  return dir;
}

// Runs the binary with `environment` (e.g. "DISPLAY=:5") prepended.
Result run(const std::string& environment, const std::string& args) {
  const std::string err_file =
      (output_dir() / ("stderr-" + std::to_string(getpid()) + ".txt")).string();
  const std::string cmd =
      environment + " " + std::string(PENUMBRA_BINARY) + " " + args + " 2>" + err_file;
  Result r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err_file);
  r.err.assign(std::istreambuf_iterator<char>(in), {});
  return r;
}

std::string out(const std::string& name) {
  const fs::path p = output_dir() / name;
  fs::remove(p);
  return p.string();
}

struct Difference {
  float max = 0.0f;
  double mean = 0.0;
};

// Over the rectangle of `a` at (0, 0) the size of `b`.
Difference difference(const Image& a, const Image& b) {
  Difference d;
  for (int y = 0; y < b.height; ++y) {
    for (int x = 0; x < b.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float e = std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]);
        d.max = std::max(d.max, e);
        d.mean += e;
      }
    }
  }
  d.mean /= 3.0 * b.width * b.height;
  return d;
}

double luminance_spread(const Image& image) {
  double sum = 0.0, squares = 0.0;
  const double n = static_cast<double>(image.width) * image.height;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const double l = (image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2]) / 3.0;
    sum += l;
    squares += l * l;
  }
  return std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n)));
}

class ViewWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!xvfb_.error().empty()) GTEST_FAIL() << xvfb_.error();
  }
  [[nodiscard]] std::string display() const { return "DISPLAY=" + xvfb_.display(); }

  // `view` of `settings` for a few scripted frames, against `render`.
  Image expect_view_matches_render(const std::string& settings, const std::string& name,
                                   const std::string& extra = "", int frames = 3) {
    const std::string shot = out(name + "-view.png");
    const std::string reference = out(name + "-render.png");
    Result v = run(display(), "view --frames " + std::to_string(frames) + " " + settings +
                                  " --screenshot " + shot + extra);
    EXPECT_EQ(v.status, 0) << v.err;
    Result r = run("", "render " + settings + " -o " + reference);
    EXPECT_EQ(r.status, 0) << r.err;
    if (!fs::exists(shot) || !fs::exists(reference)) {
      ADD_FAILURE() << "no image";
      return {};
    }
    const Image viewed = penumbra::read_png(shot);
    const Image rendered = penumbra::read_png(reference);
    EXPECT_EQ(viewed.width, rendered.width);
    EXPECT_EQ(viewed.height, rendered.height);
    if (viewed.width != rendered.width || viewed.height != rendered.height) return viewed;
    // The same Renderer on the same driver: equal but for the last bit.
    const Difference d = difference(viewed, rendered);
    EXPECT_LE(d.max, 2.0f / 255.0f) << shot << " vs " << reference;
    EXPECT_LE(d.mean, 0.25 / 255.0) << shot << " vs " << reference;
    EXPECT_GT(luminance_spread(viewed), 0.05) << shot << " looks blank";
    return viewed;
  }

 private:
  XvfbServer xvfb_;
};

constexpr const char* kSettings = "--width 320 --height 240 --shadow-map-size 1024";

TEST_F(ViewWindow, ScreenshotShowsTheShadowsRenderPutsThere) {
  const std::string window = out("window.png");
  const Image viewed = expect_view_matches_render(kSettings, "hard", " --capture-window " + window);
  ASSERT_GT(viewed.width, 0);
  // Shadows: where the unshadowed render is clearly brighter.
  const std::string unshadowed = out("none-render.png");
  ASSERT_EQ(
      run("", std::string("render ") + kSettings + " --technique none -o " + unshadowed).status, 0);
  const Image lit = penumbra::read_png(unshadowed);
  int shadowed = 0;
  for (int y = 0; y < lit.height; ++y) {
    for (int x = 0; x < lit.width; ++x) {
      if (lit.pixel(x, y)[1] - viewed.pixel(x, y)[1] > 0.1f) ++shadowed;
    }
  }
  EXPECT_GT(shadowed, lit.width * lit.height / 50) << "too few shadowed pixels";

  // The window: the view as the screenshot shows it, the panel beside it.
  ASSERT_TRUE(fs::exists(window));
  const Image captured = penumbra::read_png(window);
  ASSERT_GT(captured.width, viewed.width);
  ASSERT_EQ(captured.height, viewed.height);
  EXPECT_LE(difference(captured, viewed).max, 1.0f / 255.0f + 1e-6f);
  std::set<std::array<int, 3>> panel_colours;
  for (int y = 0; y < captured.height; ++y) {
    for (int x = viewed.width; x < captured.width; ++x) {
      const float* p = captured.pixel(x, y);
      panel_colours.insert({static_cast<int>(p[0] * 255), static_cast<int>(p[1] * 255),
                            static_cast<int>(p[2] * 255)});
    }
  }
  EXPECT_GT(panel_colours.size(), 20u) << "the panel looks empty";
}

TEST_F(ViewWindow, CameraLightAndSoftShadowsMatchRender) {
  expect_view_matches_render(
      std::string(kSettings) +
          " --technique msm --filter sat --soft --blur 3 --light-size 1.5 --view shadow"
          " --camera-position=-6,5,6 --camera-target=0,0.5,0 --light-position=-3,8,2"
          " --light-direction=0.3,-1,-0.2",
      "msm-soft");
}

// With --accumulate the viewer adds a sub-frame per still frame; once it
// has them all it shows the sum `render --accumulate` makes, and that sum
// is soft: far more pixels between lit and shadowed than one hard frame.
TEST_F(ViewWindow, AccumulatedShadowsRefineToWhatRenderMakes) {
  const std::string settings =
      std::string(kSettings) + " --technique hard --light-size 1.5 --view shadow";
  const Image viewed =
      expect_view_matches_render(settings + " --accumulate 6", "accumulate", "", 9);
  const std::string hard = out("accumulate-hard-render.png");
  ASSERT_EQ(run("", "render " + settings + " -o " + hard).status, 0);
  const auto partial = [](const Image& image) {
    int count = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
      if (image.rgba[i] > 0.1f && image.rgba[i] < 0.9f) ++count;
    }
    return count;
  };
  ASSERT_GT(viewed.width, 0);
  EXPECT_GT(partial(viewed), 3 * partial(penumbra::read_png(hard)));
}

TEST_F(ViewWindow, MapViewMatchesRender) {
  expect_view_matches_render(
      "--width 160 --height 120 --shadow-map-size 256 --technique esm --view moments-filtered "
      "--light-index 1 --light-direction=-0.5,-1,0.5",
      "esm-map");
}

// On a 1280 x 720 screen the default window (a 1280 x 720 view and the
// panel beside it) is made to fit: the view takes what the panel leaves.
// Nothing changes between the scripted frames, so one is rendered and the
// rest only drawn.
// A crash in the window's loop (a failed assert inside a library raises
// SIGABRT) ends in one "internal error" line and the signal's own status,
// like every other command's (hostile_test.cpp).
TEST_F(ViewWindow, ACrashEndsInOneLine) {
  const std::string err = out("crash-stderr.txt");
  const std::string script = display() + " " + std::string(PENUMBRA_BINARY) + " view " + kSettings +
                             " 2>" + err + " & p=$!; sleep 3; kill -ABRT $p; wait $p";
  const int raw = std::system(("bash -c '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 128 + SIGABRT);
  std::ifstream in(err);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  ASSERT_NE(text.find("penumbra: error: internal error (signal 6: "), std::string::npos) << text;
  EXPECT_EQ(text.find("penumbra: error: internal error (signal 6: "), text.rfind("penumbra: error"))
      << text;
  EXPECT_NE(text.find("please report it\n"), std::string::npos) << text;
}

TEST(ViewSmallScreen, TheWindowFitsAndAnUnchangedFrameIsNotRenderedAgain) {
  const XvfbServer xvfb("1280x720x24");
  ASSERT_TRUE(xvfb.error().empty()) << xvfb.error();
  const std::string window = out("small-screen.png");
  const Result r = run("DISPLAY=" + xvfb.display(),
                       "view --frames 8 --verbose --shadow-map-size 256 --ssao-samples 4 "
                       "--capture-window " +
                           window);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("penumbra: 8 frames drawn, 1 rendered"), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(window));
  const Image captured = penumbra::read_png(window);
  EXPECT_LE(captured.width, 1280);
  EXPECT_LE(captured.height, 720);
}

// The panel's GPU times in a real window: every row it drew names a whole
// pass and its milliseconds (read back from the rows --verbose prints).
TEST(ViewPanel, TimesNamePassesInMilliseconds) {
  const XvfbServer xvfb("1280x720x24");
  ASSERT_TRUE(xvfb.error().empty()) << xvfb.error();
  const Result r = run("DISPLAY=" + xvfb.display(),
                       "view --frames 8 --verbose --width 320 --height 240 --shadow-map-size 256 "
                       "--ssao-samples 4");
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> rows;
  const std::regex row("penumbra: (\\S.*?) +([0-9]+\\.[0-9]{3}) ms\n");
  for (std::sregex_iterator m(r.err.begin(), r.err.end(), row), end; m != end; ++m) {
    rows.push_back((*m)[1]);
  }
  ASSERT_FALSE(rows.empty()) << r.err;
  for (const std::string& name : rows) {
    const bool known = name == "GPU frame" || std::find(penumbra::gl::kGpuPassNames.begin(),
                                                        penumbra::gl::kGpuPassNames.end(),
                                                        name) != penumbra::gl::kGpuPassNames.end();
    EXPECT_TRUE(known) << "'" << name << "' is not a pass\n" << r.err;
  }
  for (const char* pass : {"shadow depth", "G-buffer", "lighting", "GPU frame"}) {
    EXPECT_NE(std::find(rows.begin(), rows.end(), pass), rows.end()) << pass << "\n" << r.err;
  }
}

TEST(ViewCommand, WithoutADisplayItSaysSoInOneLine) {
  const Result r = run("env -u DISPLAY -u WAYLAND_DISPLAY", "view --frames 1");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind("penumbra: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("display"), std::string::npos) << r.err;
}

TEST(ViewCommand, UsageErrorsComeBeforeAnyWindow) {
  const std::string shot = out("never.png");
  for (const std::string args :
       {"view --technique blurry", "view --blur -1", "view --light-position=1,2",
        "view --capture-window x.bmp", "view --frames -1"}) {
    const Result r = run("env -u DISPLAY -u WAYLAND_DISPLAY", args + " --screenshot " + shot);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(shot));
}

}  // namespace
