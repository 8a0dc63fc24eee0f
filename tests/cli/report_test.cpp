// `penumbra report --quick`: the page parses, every image it shows exists
// as a PNG of the stated size, a command under an image re-makes it, and
// headless Chromium renders the page without console errors.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "io/image.hpp"

namespace {

namespace fs = std::filesystem;

int run_shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct Figure {
  std::string src;
  int width, height;
  std::string command;
};

// Section 7: every technique's error against the traced reference of each
// of the foliage scene's two lights, and a sentence that says which is
// closest, from the same numbers.
// (Checked within WritesAPageWhoseImagesExist: each test of this suite
// runs in its own process under CTest, and so makes its own report.)
void expect_foliage_section(const std::string& html, const fs::path& dir) {
  const std::size_t begin = html.find("7. Foliage: alpha-tested casters");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = html.find("<h2>", begin);
  const std::string section = html.substr(begin, end - begin);
  EXPECT_NE(section.find("<th>RMSE directional</th><th>leaking directional</th>"
                         "<th>RMSE spot</th><th>leaking spot</th>"),
            std::string::npos)
      << section;
  // Each technique's row: RMSE and leaking for each light, all measured.
  const std::regex row_re(
      R"re(<tr><td>(\w+)</td><td>(0\.\d{4})</td><td>(\d+\.\d\d) %</td><td>(0\.\d{4})</td><td>(\d+\.\d\d) %</td></tr>)re");
  std::map<std::string, std::pair<double, double>> rmse;  // technique -> (sun, spot)
  for (std::sregex_iterator it(section.begin(), section.end(), row_re), stop; it != stop; ++it) {
    rmse[(*it)[1].str()] = {std::stod((*it)[2].str()), std::stod((*it)[4].str())};
  }
  for (const char* technique : {"hard", "pcf", "pcss", "vsm", "msm"}) {
    ASSERT_EQ(rmse.count(technique), 1u) << technique << " has no row:\n" << section;
    // A shadow factor in [0, 1] over many pixels: an error, not 0 or garbage.
    EXPECT_GT(rmse[technique].first, 0.0) << technique;
    EXPECT_LT(rmse[technique].first, 0.5) << technique;
    EXPECT_GT(rmse[technique].second, 0.0) << technique;
    EXPECT_LT(rmse[technique].second, 0.5) << technique;
  }
  // The sentence names the technique of the smallest RMSE, with that RMSE.
  for (const bool sun : {true, false}) {
    const auto best = std::min_element(rmse.begin(), rmse.end(), [&](auto& a, auto& b) {
      return sun ? a.second.first < b.second.first : a.second.second < b.second.second;
    });
    std::ostringstream expected;
    expected.setf(std::ios::fixed);
    expected.precision(4);
    expected << "Under the " << (sun ? "directional" : "spot") << " light, " << best->first
             << " is closest to the traced reference (RMSE "
             << (sun ? best->second.first : best->second.second) << ").";
    EXPECT_NE(section.find(expected.str()), std::string::npos) << expected.str() << "\n" << section;
  }
  for (const char* image : {"foliage-spot-traced.png", "foliage-directional-traced.png",
                            "foliage-spot-error-vsm.png", "foliage-directional-error-pcss.png"}) {
    EXPECT_NE(section.find(std::string("<img src=\"") + image + "\""), std::string::npos) << image;
  }
  // The scene's files are in the report's folder, for the commands.
  EXPECT_TRUE(fs::exists(dir / "foliage" / "foliage.gltf"));
  EXPECT_TRUE(fs::exists(dir / "foliage" / "leaves.png"));
}

class Report : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // CTest may run this binary's tests in parallel processes: each makes
    // its own report.
    dir_ = fs::path(PENUMBRA_TEST_OUTPUT) / ("report-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    status_ = run_shell(std::string(PENUMBRA_BINARY) + " report --quick -o " + dir_.string() +
                        " > " + (dir_ / "stdout.txt").string());
    html_ = read_file(dir_ / "index.html");
    // <img src="F" width="W" height="H" ...> followed in its figure by <code>COMMAND</code>
    const std::regex figure_re(
        R"re(<img src="([^"]+)" width="(\d+)" height="(\d+)"[^>]*><figcaption>[^<]*<code>([^<]+)</code>)re");
    const std::regex image_re(R"re(<img src="([^"]+)" width="(\d+)" height="(\d+)")re");
    for (std::sregex_iterator it(html_.begin(), html_.end(), image_re), end; it != end; ++it) {
      images_.push_back({(*it)[1].str(), std::stoi((*it)[2].str()), std::stoi((*it)[3].str()), ""});
    }
    for (std::sregex_iterator it(html_.begin(), html_.end(), figure_re), end; it != end; ++it) {
      std::string command = (*it)[4].str();
      command = std::regex_replace(command, std::regex("&quot;"), "\"");
      figures_.push_back(
          {(*it)[1].str(), std::stoi((*it)[2].str()), std::stoi((*it)[3].str()), command});
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static inline fs::path dir_;
  static inline int status_ = -1;
  static inline std::string html_;
  static inline std::vector<Figure> figures_;  // images with the command that re-makes them
  static inline std::vector<Figure> images_;   // every image on the page
};

TEST_F(Report, WritesAPageWhoseImagesExist) {
  ASSERT_EQ(status_, 0);
  EXPECT_EQ(html_.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html_.find("</html>"), std::string::npos);
  EXPECT_EQ(html_.find("<script"), std::string::npos) << "the page must be self-contained";
  EXPECT_EQ(html_.find("http"), std::string::npos) << "the page must need no network";
  for (const char* section :
       {"1. The techniques", "2. Spot, point and directional lights",
        "3. Shadow maps before and after", "4. From anti-aliased to soft", "5. The ESM exponent c",
        "6. Errors against", "7. Foliage: alpha-tested casters", "8. GPU time per pass"}) {
    EXPECT_NE(html_.find(section), std::string::npos) << section;
  }
  EXPECT_EQ(html_.find("<div class=\"failed\">"), std::string::npos) << "an item failed";
  expect_foliage_section(html_, dir_);
  ASSERT_GE(figures_.size(), 30u);
  ASSERT_GE(images_.size(), figures_.size() + 7) << "the error images are missing";
  for (const Figure& f : images_) {
    const fs::path path = dir_ / f.src;
    ASSERT_TRUE(fs::exists(path)) << f.src;
    const std::string bytes = read_file(path);
    ASSERT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << f.src;
    const penumbra::Image image = penumbra::read_png(path.string());
    EXPECT_EQ(image.width, f.width) << f.src;
    EXPECT_EQ(image.height, f.height) << f.src;
  }
}

TEST_F(Report, TheCommandUnderAnImageRemakesIt) {
  ASSERT_EQ(status_, 0);
  // Spot-check a filtered technique's image under the scene's lights and
  // under a point light alone (--light), and the foliage scene (its glTF
  // written next to the page): its command, run in the report's folder,
  // writing to another name.
  for (const std::string name : {"technique-msm.png", "light-point-msm.png", "foliage.png"}) {
    const auto chosen = std::find_if(figures_.begin(), figures_.end(),
                                     [&](const Figure& f) { return f.src == name; });
    ASSERT_NE(chosen, figures_.end()) << name;
    std::string command = chosen->command;
    ASSERT_EQ(command.rfind("penumbra render ", 0), 0u) << command;
    command.replace(0, std::string("penumbra").size(), PENUMBRA_BINARY);
    command = std::regex_replace(command, std::regex(" --output=\\S+$"), " --output=remade.png");
    ASSERT_EQ(run_shell("cd " + dir_.string() + " && " + command), 0) << command;
    const penumbra::Image original = penumbra::read_png((dir_ / chosen->src).string());
    const penumbra::Image remade = penumbra::read_png((dir_ / "remade.png").string());
    ASSERT_EQ(original.width, remade.width);
    ASSERT_EQ(original.height, remade.height);
    EXPECT_EQ(original.rgba, remade.rgba) << command;
  }
}

TEST_F(Report, ChromiumShowsThePageWithoutConsoleErrors) {
  ASSERT_EQ(status_, 0);
  ASSERT_EQ(run_shell("command -v chromium > /dev/null"), 0)
      << "chromium is missing: scripts/install-deps installs it";
  const fs::path shot = dir_ / "screenshot.png";
  const fs::path log = dir_ / "chromium.log";
  fs::remove(shot);
  const std::string command =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--user-data-dir=" +
      (dir_ / "chromium-profile").string() +
      " --enable-logging=stderr --v=0 --window-size=1400,2000 --screenshot=" + shot.string() +
      " file://" + fs::absolute(dir_ / "index.html").string() + " 2> " + log.string();
  EXPECT_EQ(run_shell(command), 0);
  ASSERT_TRUE(fs::exists(shot));
  const penumbra::Image image = penumbra::read_png(shot.string());
  EXPECT_EQ(image.width, 1400);
  // Chromium logs page console messages and failed loads as CONSOLE lines.
  const std::string messages = read_file(log);
  EXPECT_EQ(messages.find("CONSOLE"), std::string::npos) << messages;
  EXPECT_EQ(messages.find("Failed to load resource"), std::string::npos) << messages;
}

}  // namespace
