// `penumbra report --quick`: the page parses, every image it shows exists
// as a PNG of the stated size and links to its full-size file, a command
// under an image re-makes it, the plots draw the numbers the tables print,
// the close-ups are cut from the regions the error images mark, the
// verdict's numbers are the ones its sections show, and headless Chromium
// renders the page without console errors. All tests share one report.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "io/image.hpp"
#include "penumbra/settings.hpp"
#include "reference/error_image.hpp"
#include "render/pass_timing.hpp"

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

// Section 8: every technique's error against the traced reference of each
// of the foliage scene's two lights, and a sentence that says which is
// closest, from the same numbers.
void expect_foliage_section(const std::string& html, const fs::path& dir) {
  const std::size_t begin = html.find("8. Foliage: alpha-tested casters");
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
  // The cut-outs re-measured at 512^2, 1024^2 and 2048^2 maps: per light,
  // hard's RMSE and total shadow at each size, and at the study's own map
  // size (512^2 here) the very RMSE of the table above.
  const std::regex size_row_re(
      R"re(<tr><td>(\w+)</td><td>hard</td><td>(0\.\d{4})</td><td>(0\.\d{4})</td><td>(0\.\d{4})</td><td>(\d\.\d{3})</td><td>(\d\.\d{3})</td><td>(\d\.\d{3})</td></tr>)re");
  EXPECT_NE(section.find("<th>RMSE 512^2</th><th>RMSE 1024^2</th><th>RMSE 2048^2</th>"
                         "<th>total shadow 512^2</th>"),
            std::string::npos)
      << section;
  int size_rows = 0;
  for (std::sregex_iterator it(section.begin(), section.end(), size_row_re), stop; it != stop;
       ++it, ++size_rows) {
    const bool sun = (*it)[1].str() == "directional";
    EXPECT_DOUBLE_EQ(std::stod((*it)[2].str()), sun ? rmse["hard"].first : rmse["hard"].second);
    for (int size = 0; size < 3; ++size) {
      // As much shadow as the reference, give or take the edges' texels.
      const double shadow = std::stod((*it)[5 + size].str());
      EXPECT_GT(shadow, 0.5) << (*it)[0].str();
      EXPECT_LT(shadow, 1.5) << (*it)[0].str();
    }
  }
  EXPECT_EQ(size_rows, 2) << "hard under each light:\n" << section;
  // The scene's files are in the report's folder, for the commands.
  EXPECT_TRUE(fs::exists(dir / "foliage" / "foliage.gltf"));
  EXPECT_TRUE(fs::exists(dir / "foliage" / "leaves.png"));
}

using Table = std::vector<std::vector<std::string>>;

// The HTML of <section id="id"> (empty if there is none).
std::string section_of(const std::string& html, const std::string& id) {
  const std::size_t begin = html.find("<section id=\"" + id + "\">");
  if (begin == std::string::npos) return "";
  return html.substr(begin, html.find("</section>", begin) - begin);
}

// Every <table> in `html`, as rows of cell texts (header row first).
std::vector<Table> tables_of(const std::string& html) {
  std::vector<Table> tables;
  const std::regex table_re(R"re(<table>([\s\S]*?)</table>)re");
  const std::regex row_re(R"re(<tr>([\s\S]*?)</tr>)re");
  const std::regex cell_re(R"re(<t[hd]>([^<]*)</t[hd]>)re");
  for (std::sregex_iterator t(html.begin(), html.end(), table_re), end; t != end; ++t) {
    Table table;
    const std::string body = (*t)[1].str();
    for (std::sregex_iterator r(body.begin(), body.end(), row_re); r != end; ++r) {
      const std::string row = (*r)[1].str();
      table.emplace_back();
      for (std::sregex_iterator c(row.begin(), row.end(), cell_re); c != end; ++c) {
        table.back().push_back((*c)[1].str());
      }
    }
    tables.push_back(table);
  }
  return tables;
}

// The column of a table's header named `name` (-1 if none).
int column_of(const Table& table, const std::string& name) {
  const auto it = std::find(table.front().begin(), table.front().end(), name);
  return it == table.front().end() ? -1 : static_cast<int>(it - table.front().begin());
}

// The row whose first cell is `key` (nullptr if none).
const std::vector<std::string>* row_of(const Table& table, const std::string& key) {
  for (const auto& row : table) {
    if (!row.empty() && row.front() == key) return &row;
  }
  return nullptr;
}

struct PlotPoint {
  std::string series;
  double x, y;
  bool filled;
};
struct Bar {
  std::string category, series;
  double value;
};
struct Plot {
  std::string title;
  std::vector<PlotPoint> points;
  std::vector<Bar> bars;
  Table data;  // the table under its <details>
};

std::vector<Plot> plots_of(const std::string& html) {
  std::vector<Plot> plots;
  const std::regex plot_re(R"re(<figure class="plot">([\s\S]*?)</figure>)re");
  const std::regex title_re(R"re(<title>([^<]*)</title>)re");
  const std::regex point_re(
      R"re(class="point" data-series="([^"]+)" data-x="([^"]+)" data-y="([^"]+)" d="[^"]*" fill="([^"]+)" stroke="([^"]+)")re");
  const std::regex bar_re(
      R"re(class="bar" data-category="([^"]+)" data-series="([^"]+)" data-value="([^"]+)")re");
  for (std::sregex_iterator p(html.begin(), html.end(), plot_re), end; p != end; ++p) {
    const std::string body = (*p)[1].str();
    Plot plot;
    std::smatch title;
    if (std::regex_search(body, title, title_re)) plot.title = title[1].str();
    for (std::sregex_iterator it(body.begin(), body.end(), point_re); it != end; ++it) {
      plot.points.push_back({(*it)[1].str(), std::stod((*it)[2].str()), std::stod((*it)[3].str()),
                             (*it)[4].str() == (*it)[5].str()});
    }
    for (std::sregex_iterator it(body.begin(), body.end(), bar_re); it != end; ++it) {
      plot.bars.push_back({(*it)[1].str(), (*it)[2].str(), std::stod((*it)[3].str())});
    }
    const std::vector<Table> tables = tables_of(body.substr(body.find("<details>")));
    if (!tables.empty()) plot.data = tables.front();
    plots.push_back(plot);
  }
  return plots;
}

const Plot* plot_titled(const std::vector<Plot>& plots, const std::string& title) {
  for (const Plot& p : plots) {
    if (p.title == title) return &p;
  }
  return nullptr;
}

// A number as a table prints it ("0.632 %" reads 0.632).
double number(const std::string& cell) {
  return std::stod(cell);
}

class Report : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // CTest runs each test in a process of its own (in parallel with -j):
    // they share one report, made by the first under a lock and reused by
    // the others while it is recent and the binary that made it unchanged.
    const fs::path shared = fs::path(PENUMBRA_TEST_OUTPUT) / "report-quick";
    dir_ = shared / "report";
    fs::create_directories(shared);
    const int lock = open((shared / "lock").c_str(), O_CREAT | O_RDWR, 0644);
    ASSERT_GE(lock, 0);
    ASSERT_EQ(flock(lock, LOCK_EX), 0);
    const fs::path stamp = shared / "made-by";
    const std::string maker = binary_identity();
    const bool fresh = read_file(stamp) == maker && fs::exists(dir_ / "index.html") &&
                       fs::exists(shared / "stderr.txt") &&
                       fs::last_write_time(stamp) > fs::file_time_type::clock::now() - kReuseFor;
    if (fresh) {
      status_ = 0;
    } else {
      fs::remove(stamp);
      fs::remove_all(dir_);
      fs::create_directories(dir_);
      // Its own temporary folder, which the shader rehearsal's files must
      // leave empty.
      fs::remove_all(temporary_dir());
      fs::create_directories(temporary_dir());
      status_ =
          run_shell("TMPDIR=" + temporary_dir().string() + " " + PENUMBRA_BINARY +
                    " report --quick -o " + dir_.string() + " > " +
                    (shared / "stdout.txt").string() + " 2> " + (shared / "stderr.txt").string());
      if (status_ == 0) std::ofstream(stamp) << maker;
    }
    flock(lock, LOCK_UN);
    close(lock);
    stderr_ = read_file(shared / "stderr.txt");
    html_ = read_file(dir_ / "index.html");
    // <img src="F" width="W" height="H" ...> followed in its figure by <code>COMMAND</code>
    const std::regex figure_re(
        R"re(<img src="([^"]+)" width="(\d+)" height="(\d+)"[^>]*>(?:<span[^>]*>[^<]*</span>)*</a><figcaption>[^<]*<code>([^<]+)</code>)re");
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
  static fs::path temporary_dir() {
    return fs::path(PENUMBRA_TEST_OUTPUT) / "report-quick" / "tmp";
  }
  // The binary's size and modification time: a rebuilt binary makes a new report.
  static std::string binary_identity() {
    const fs::path binary(PENUMBRA_BINARY);
    return std::to_string(fs::file_size(binary)) + " " +
           std::to_string(fs::last_write_time(binary).time_since_epoch().count());
  }
  // Long enough for one ctest run of the suite, short enough that a later
  // run makes its own report.
  static constexpr auto kReuseFor = std::chrono::minutes(20);
  static inline fs::path dir_;
  static inline int status_ = -1;
  static inline std::string html_;
  static inline std::string stderr_;           // the report's progress, not on a terminal
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
       {"<section id=\"summary\">", "1. The techniques", "2. Spot, point and directional lights",
        "3. Shadow maps before and after", "4. From anti-aliased to soft", "5. The ESM exponent c",
        "6. Errors against", "7. Close-ups at 4x", "8. Foliage: alpha-tested casters",
        "9. GPU time and memory traffic per pass", "10. Cascades or virtual maps"}) {
    EXPECT_NE(html_.find(section), std::string::npos) << section;
  }
  EXPECT_LT(html_.find("<section id=\"summary\">"), html_.find("1. The techniques"))
      << "the verdict comes first";
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
  // under a point light alone (--light), a sweep's frame (the measured
  // light alone), and the foliage scene (its glTF written next to the
  // page): its command, run in the report's folder, writing to another
  // name.
  for (const std::string name :
       {"technique-msm.png", "light-point-msm.png", "sweep-msm-w16.png", "foliage.png"}) {
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

TEST_F(Report, EveryImageLinksToItsFullSizeFile) {
  ASSERT_EQ(status_, 0);
  const std::regex link_re(
      R"re(<a class="frame" href="([^"]+)"><img src="([^"]+)" width="(\d+)")re");
  int links = 0, crops = 0;
  for (std::sregex_iterator it(html_.begin(), html_.end(), link_re), end; it != end; ++it) {
    ++links;
    const std::string link = (*it)[1].str(), src = (*it)[2].str();
    ASSERT_TRUE(fs::exists(dir_ / link)) << link;
    if (link == src) continue;
    // A close-up links to the whole image it was cut from.
    ++crops;
    EXPECT_EQ(src.rfind("crop-", 0), 0u) << src;
    const penumbra::Image full = penumbra::read_png((dir_ / link).string());
    EXPECT_EQ(full.width * 4 % std::stoi((*it)[3].str()), 0) << link;
    EXPECT_GT(full.width * 4, std::stoi((*it)[3].str())) << link;
  }
  EXPECT_EQ(static_cast<std::size_t>(links), images_.size()) << "an image without its link";
  EXPECT_GE(crops, 30);
}

TEST_F(Report, MapsBeforeAndAfterTheBlurStayTogether) {
  ASSERT_EQ(status_, 0);
  const std::string maps = section_of(html_, "maps");
  const std::regex group_re(
      R"re(<div class="group">\s*<figure><a class="frame" href="map-([a-z0-9]+)\.png">[\s\S]*?</figure>\s*<figure><a class="frame" href="map-([a-z0-9]+)-blurred\.png">[\s\S]*?</figure>\s*</div>)re");
  int pairs = 0;
  for (std::sregex_iterator it(maps.begin(), maps.end(), group_re), end; it != end; ++it) {
    EXPECT_EQ((*it)[1].str(), (*it)[2].str());
    ++pairs;
  }
  EXPECT_EQ(pairs, 6);
}

TEST_F(Report, NoTableHasAnEmptyColumn) {
  ASSERT_EQ(status_, 0);
  const std::vector<Table> tables = tables_of(html_);
  ASSERT_GE(tables.size(), 8u);
  for (const Table& table : tables) {
    if (table.size() < 2) continue;
    for (std::size_t c = 0; c < table.front().size(); ++c) {
      const bool filled = std::any_of(table.begin() + 1, table.end(), [&](const auto& row) {
        return c < row.size() && !row[c].empty();
      });
      EXPECT_TRUE(filled) << "column '" << table.front()[c] << "' is empty";
    }
  }
}

TEST_F(Report, PlotsDrawTheNumbersTheTablesPrint) {
  ASSERT_EQ(status_, 0);
  const std::vector<Plot> plots = plots_of(html_);
  for (const char* title : {"Error against filter width", "Error against light size",
                            "ESM: leaking and over-darkening against c", "Quality against cost",
                            "Memory traffic per shadow-map texel"}) {
    const Plot* plot = plot_titled(plots, title);
    ASSERT_NE(plot, nullptr) << title;
    EXPECT_FALSE(plot->points.empty() && plot->bars.empty()) << title;
    EXPECT_GE(plot->data.size(), 2u) << title;
  }
  // Error against width: a point per row of its table (technique, W, RMSE).
  const Plot& widths = *plot_titled(plots, "Error against filter width");
  ASSERT_EQ(widths.points.size() + 1, widths.data.size());
  for (std::size_t i = 0; i < widths.points.size(); ++i) {
    EXPECT_EQ(widths.points[i].series, widths.data[i + 1][0]);
    EXPECT_EQ(widths.points[i].x, number(widths.data[i + 1][1]));
    EXPECT_NEAR(widths.points[i].y, number(widths.data[i + 1][2]), 0.5e-4);
  }
  // Error against light size: the table's row of each size, column of each series.
  const Plot& sizes = *plot_titled(plots, "Error against light size");
  ASSERT_GE(sizes.points.size(), 15u);
  for (const PlotPoint& p : sizes.points) {
    const int column = column_of(sizes.data, "RMSE " + p.series);
    ASSERT_GE(column, 0) << p.series;
    char size[16];
    std::snprintf(size, sizeof size, "%.2f", p.x);
    const auto* row = row_of(sizes.data, size);
    ASSERT_NE(row, nullptr) << size;
    EXPECT_NEAR(p.y, number((*row)[column]), 0.5e-4) << p.series << " at " << size;
  }
  // ESM: the section's own table of measurements, not only the plot's.
  const Table esm = tables_of(section_of(html_, "esm")).front();
  const Plot& leaks = *plot_titled(plots, "ESM: leaking and over-darkening against c");
  ASSERT_EQ(leaks.points.size(), 2 * (esm.size() - 1));
  for (const PlotPoint& p : leaks.points) {
    const auto* row = row_of(esm, std::to_string(static_cast<int>(std::lround(p.x))));
    ASSERT_NE(row, nullptr) << p.x;
    const int column = column_of(esm, p.series);
    ASSERT_GE(column, 0) << p.series;
    EXPECT_NEAR(p.y, number((*row)[column]), 0.5e-3) << p.series << " at c = " << p.x;
  }
  // Quality against cost: the timing table's total and the errors table's
  // RMSE of each technique; filled exactly where no other point is better
  // in both.
  const Table times = tables_of(section_of(html_, "timings")).front();
  const Table errors = tables_of(section_of(html_, "errors")).front();
  const Plot& cost = *plot_titled(plots, "Quality against cost");
  ASSERT_EQ(cost.points.size(), 10u);
  for (std::size_t i = 0; i < cost.points.size(); ++i) {
    const PlotPoint& p = cost.points[i];
    const std::string name = cost.data[i + 1][0];
    EXPECT_NEAR(p.x, number((*row_of(times, name))[column_of(times, "total")]), 0.5e-2) << name;
    EXPECT_NEAR(p.y, number((*row_of(errors, name))[column_of(errors, "RMSE traced")]), 0.5e-4)
        << name;
    bool dominated = false;
    for (const PlotPoint& q : cost.points) {
      dominated |= q.x <= p.x && q.y <= p.y && (q.x < p.x || q.y < p.y);
    }
    EXPECT_EQ(p.filled, !dominated) << name;
    EXPECT_EQ(cost.data[i + 1][3], dominated ? "no" : "yes") << name;
  }
  // Bytes per texel: the bars are the table's reads + writes, and the
  // table is the passes' own accounting.
  const Plot& bytes = *plot_titled(plots, "Memory traffic per shadow-map texel");
  ASSERT_FALSE(bytes.bars.empty());
  for (const Bar& bar : bytes.bars) {
    const auto* row = row_of(bytes.data, bar.category);
    ASSERT_NE(row, nullptr) << bar.category;
    const std::string cell = (*row)[column_of(bytes.data, bar.series + " (read + written)")];
    const std::size_t plus = cell.find(" + ");
    ASSERT_NE(plus, std::string::npos) << cell;
    EXPECT_NEAR(bar.value, number(cell.substr(0, plus)) + number(cell.substr(plus + 3)), 1e-3)
        << bar.category << ", " << bar.series;
  }
  penumbra::ShadowSettings vsm;
  vsm.technique = penumbra::Technique::Vsm;
  vsm.blur = 4;
  vsm.map_size = 512;  // --quick
  const auto traffic = penumbra::shadow_map_traffic(vsm, vsm.map_size, vsm.map_size);
  double total = 0.0;
  for (std::size_t p = 0; p < traffic.size(); ++p) {
    if (traffic[p] && p != static_cast<std::size_t>(penumbra::gl::GpuPass::BandwidthCopy)) {
      total += traffic[p]->total();
    }
  }
  double drawn = 0.0;
  for (const Bar& bar : bytes.bars) drawn += bar.category == "vsm" ? bar.value : 0.0;
  EXPECT_NEAR(drawn, total, 1e-6);
}

TEST_F(Report, CloseUpsAreCutFromTheRegionsTheErrorImagesMark) {
  ASSERT_EQ(status_, 0);
  const std::string closeups = section_of(html_, "closeups");
  const Table regions = tables_of(closeups).front();
  ASSERT_EQ(regions.size(), 4u);
  // The boxes on every error image: region i at its place, in percent.
  const std::string errors = section_of(html_, "errors");
  const penumbra::Image traced = penumbra::read_png((dir_ / "shadow-traced.png").string());
  const std::regex box_re(
      R"re(<span class="region" style="left:([0-9.]+)%;top:([0-9.]+)%;width:([0-9.]+)%;height:([0-9.]+)%">(\d)</span>)re");
  int boxes = 0;
  for (std::sregex_iterator it(errors.begin(), errors.end(), box_re), end; it != end; ++it) {
    const auto& region = regions[std::stoi((*it)[5].str())];
    EXPECT_NEAR(std::stod((*it)[1].str()) * traced.width / 100.0, number(region[1]), 1e-2);
    EXPECT_NEAR(std::stod((*it)[2].str()) * traced.height / 100.0, number(region[2]), 1e-2);
    EXPECT_NEAR(std::stod((*it)[3].str()) * traced.width / 100.0, number(region[3]), 1e-2);
    ++boxes;
  }
  EXPECT_EQ(boxes, 3 * 12) << "three boxes on each of the twelve error images";

  // Each close-up: its region, 4x nearest neighbour, of the image it links to.
  const std::regex crop_re(
      R"re(<figure class="crop" data-region="([a-z-]+)" data-source="([^"]+)" data-x="(\d+)" data-y="(\d+)" data-width="(\d+)" data-height="(\d+)" data-scale="(\d+)"><a class="frame" href="([^"]+)"><img src="([^"]+)")re");
  int crops = 0;
  std::vector<std::string> sources;
  for (std::sregex_iterator it(closeups.begin(), closeups.end(), crop_re), end; it != end; ++it) {
    const std::string region = (*it)[1].str();
    const int x = std::stoi((*it)[3].str()), y = std::stoi((*it)[4].str());
    const int w = std::stoi((*it)[5].str()), h = std::stoi((*it)[6].str());
    const int scale = std::stoi((*it)[7].str());
    EXPECT_EQ(scale, 4);
    EXPECT_EQ((*it)[2].str(), (*it)[8].str());
    const int index = region == "largest-error" ? 1 : region == "contact-shadow" ? 2 : 3;
    EXPECT_EQ(x, number(regions[index][1])) << region;
    EXPECT_EQ(y, number(regions[index][2])) << region;
    const penumbra::Image source = penumbra::read_png((dir_ / (*it)[2].str()).string());
    const penumbra::Image crop = penumbra::read_png((dir_ / (*it)[9].str()).string());
    ASSERT_EQ(crop.width, w * scale);
    ASSERT_EQ(crop.height, h * scale);
    bool same = true;
    for (int cy = 0; cy < crop.height && same; ++cy) {
      for (int cx = 0; cx < crop.width && same; ++cx) {
        const float* c = crop.pixel(cx, cy);
        const float* s = source.pixel(x + cx / scale, y + cy / scale);
        same = std::equal(c, c + 4, s);
      }
    }
    EXPECT_TRUE(same) << (*it)[9].str() << " is not its region of " << (*it)[2].str();
    if (region == "largest-error") sources.push_back((*it)[2].str());
    ++crops;
  }
  EXPECT_EQ(crops, 3 * 13) << "three regions of the reference and twelve settings";

  // The largest-error region holds (up to 8-bit rounding) the most summed
  // |technique - reference| of any window its size.
  ASSERT_EQ(sources.size(), 13u);
  const int w = static_cast<int>(number(regions[1][3])),
            h = static_cast<int>(number(regions[1][4]));
  std::vector<double> error(static_cast<std::size_t>(traced.width) * traced.height, 0.0);
  // The pixels the reference judges: its PNG has no alpha, but the error
  // images paint the others in their background grey.
  const penumbra::Image judged = penumbra::read_png((dir_ / "error-hard.png").string());
  const auto background = [&](int px, int py) {
    const float* e = judged.pixel(px, py);
    return std::abs(e[0] - penumbra::kErrorImageBackground) < 1.5f / 255.0f && e[0] == e[1] &&
           e[1] == e[2];
  };
  for (const std::string& source : sources) {
    if (source == "shadow-traced.png") continue;
    const penumbra::Image image = penumbra::read_png((dir_ / source).string());
    for (int py = 0; py < traced.height; ++py) {
      for (int px = 0; px < traced.width; ++px) {
        if (background(px, py)) continue;
        error[static_cast<std::size_t>(py) * traced.width + px] +=
            std::abs(image.pixel(px, py)[0] - traced.pixel(px, py)[0]);
      }
    }
  }
  const auto window = [&](int x0, int y0) {
    double sum = 0.0;
    for (int py = y0; py < y0 + h; ++py) {
      for (int px = x0; px < x0 + w; ++px)
        sum += error[static_cast<std::size_t>(py) * traced.width + px];
    }
    return sum;
  };
  double most = 0.0;
  for (int y0 = 0; y0 + h <= traced.height; y0 += 2) {
    for (int x0 = 0; x0 + w <= traced.width; x0 += 2) most = std::max(most, window(x0, y0));
  }
  EXPECT_GE(
      window(static_cast<int>(number(regions[1][1])), static_cast<int>(number(regions[1][2]))),
      0.98 * most);
}

TEST_F(Report, TheVerdictsNumbersAppearInTheSectionsItLinks) {
  ASSERT_EQ(status_, 0);
  const std::string summary = section_of(html_, "summary");
  const std::regex line_re(
      R"re(<li><b>([^<]+)</b>[^<]*<data value="([^"]+)">[^<]*</data>[^<]*<a href="#([a-z]+)">)re");
  int lines = 0;
  for (std::sregex_iterator it(summary.begin(), summary.end(), line_re), end; it != end; ++it) {
    const std::string when = (*it)[1].str(), value = (*it)[2].str(), id = (*it)[3].str();
    const std::string section = section_of(html_, id);
    ASSERT_FALSE(section.empty()) << when << " links to a missing section #" << id;
    // As a table cell (possibly with its unit), or a plot's data.
    EXPECT_TRUE(section.find(">" + value + "<") != std::string::npos ||
                section.find(">" + value + " ") != std::string::npos)
        << when << ": " << value << " is not in section #" << id;
    ++lines;
  }
  EXPECT_GE(lines, 5);
  for (const char* when :
       {"Hard contact shadows", "Wide soft light", "Tight memory budget", "Large scenes"}) {
    EXPECT_NE(summary.find(when), std::string::npos) << when;
  }
}

TEST_F(Report, TiesAreCalledTies) {
  ASSERT_EQ(status_, 0);
  // The ESM sweep's least mean error, as its table prints it.
  const std::string esm = section_of(html_, "esm");
  const Table table = tables_of(esm).front();
  std::vector<std::string> best;
  std::string least;
  for (std::size_t r = 1; r < table.size(); ++r) {
    if (least.empty() || number(table[r][1]) < number(least)) least = table[r][1], best.clear();
    if (table[r][1] == least) best.push_back(table[r][0]);
  }
  ASSERT_FALSE(best.empty());
  if (best.size() > 1) {
    EXPECT_NE(esm.find("tie for the least mean error, " + least), std::string::npos) << least;
  } else {
    EXPECT_NE(esm.find("c = " + best.front() + " measures the least mean error, " + least),
              std::string::npos);
  }
  EXPECT_EQ(esm.find(" wins"), std::string::npos);
}

TEST_F(Report, NotOnATerminalProgressIsOneLinePerStepThenTheCost) {
  ASSERT_EQ(status_, 0);
  // One line as each section begins, in the page's order, with the count
  // of items done and the time so far; then wall, CPU and peak memory.
  const std::regex step_re(
      R"re(report: (\d)\. [^(\n]+ \((\d+) of (\d+) items done, [0-9.]+ s, [0-9.]+ s CPU\)\n)re");
  int expected = 1;
  int last_done = -1;
  for (std::sregex_iterator it(stderr_.begin(), stderr_.end(), step_re), end; it != end; ++it) {
    EXPECT_EQ(std::stoi((*it)[1].str()), expected) << stderr_;
    ++expected;
    EXPECT_GE(std::stoi((*it)[2].str()), last_done);
    last_done = std::stoi((*it)[2].str());
    EXPECT_LE(last_done, std::stoi((*it)[3].str())) << "the count runs past its total";
  }
  EXPECT_EQ(expected, 10) << "nine sections, nine lines:\n" << stderr_;
  // The last step, the page, begins when every item is done: the total the
  // bar and its estimate use is the real one.
  std::smatch last;
  ASSERT_TRUE(std::regex_search(
      stderr_, last, std::regex(R"re(report: the verdict and the page \((\d+) of (\d+) items)re")));
  EXPECT_EQ(last[1].str(), last[2].str());
  EXPECT_TRUE(std::regex_search(
      stderr_, std::regex(R"re(\nreport: [0-9.]+ s wall, [0-9.]+ s CPU, \d+ MB peak memory\n$)re")))
      << stderr_;
  EXPECT_EQ(stderr_.find('\r'), std::string::npos) << "no bar drawn outside a terminal";
}

// On llvmpipe a second thread rehearses the study at a tiny size so that
// the shaders are compiled ahead (report/shader_rehearsal.hpp), in a
// temporary folder of its own: gone when the report is.
TEST_F(Report, TheShaderRehearsalLeavesNoFileBehind) {
  ASSERT_EQ(status_, 0);
  ASSERT_TRUE(fs::is_directory(temporary_dir()));
  EXPECT_TRUE(fs::is_empty(temporary_dir())) << temporary_dir();
}

TEST_F(Report, AQuickReportSaysSoAndWhatDiffers) {
  ASSERT_EQ(status_, 0);
  const std::size_t banner = html_.find("<p class=\"banner\">This is the quick report (--quick)");
  ASSERT_NE(banner, std::string::npos);
  EXPECT_LT(banner, html_.find("<section id=\"summary\">")) << "the banner comes first";
  const std::string text = html_.substr(banner, html_.find("</p>", banner) - banner);
  // What --quick changes, as the study ran it: its frames are 320x180.
  const auto technique = std::find_if(images_.begin(), images_.end(), [](const Figure& f) {
    return f.src == "technique-hard.png";
  });
  ASSERT_NE(technique, images_.end());
  EXPECT_NE(text.find("frames of " + std::to_string(technique->width) + "x" +
                      std::to_string(technique->height) + " instead of 640x360"),
            std::string::npos)
      << text;
  for (const char* what :
       {"shadow maps of 512^2 instead of 2048^2", "64 rays per pixel instead of 256", "README"}) {
    EXPECT_NE(text.find(what), std::string::npos) << what << " in: " << text;
  }
}

TEST_F(Report, TimesOfAnEmulatedGpuAreNotCalledAGpuRanking) {
  ASSERT_EQ(status_, 0);
  // The suite runs on llvmpipe: every time is the CPU's.
  const std::string summary = section_of(html_, "summary");
  EXPECT_NE(summary.find("<b>Most quality per millisecond (CPU emulation, not a GPU ranking):</b>"),
            std::string::npos)
      << summary;
  const std::string timings = section_of(html_, "timings");
  EXPECT_NE(timings.find("frame time on a GPU emulated on the CPU"), std::string::npos);
  EXPECT_EQ(timings.find("GPU time per frame"), std::string::npos);
}

TEST_F(Report, ImagesAreNeverEnlargedAndRowsKeepOneHeight) {
  ASSERT_EQ(status_, 0);
  const std::regex shown_re(
      R"re(<img src="([^"]+)" width="(\d+)" height="(\d+)"[^>]*style="width:(\d+)px;height:(\d+)px">)re");
  int shown = 0;
  for (std::sregex_iterator it(html_.begin(), html_.end(), shown_re), end; it != end; ++it) {
    ++shown;
    EXPECT_LE(std::stoi((*it)[4].str()), std::stoi((*it)[2].str())) << (*it)[1].str();
    EXPECT_LE(std::stoi((*it)[5].str()), std::stoi((*it)[3].str())) << (*it)[1].str();
  }
  EXPECT_EQ(static_cast<std::size_t>(shown), images_.size()) << "an image without its shown size";
  // Section 2's square shadow maps are shown as tall as its 16:9 frames.
  const std::string lights = section_of(html_, "lights");
  std::smatch frame, map;
  ASSERT_TRUE(std::regex_search(
      lights, frame,
      std::regex(R"re(src="light-spot-hard\.png"[^>]*style="width:\d+px;height:(\d+)px")re")));
  ASSERT_TRUE(std::regex_search(
      lights, map,
      std::regex(
          R"re(src="light-spot-shadow-map\.png"[^>]*style="width:(\d+)px;height:(\d+)px")re")));
  EXPECT_EQ(map[2].str(), frame[1].str());
}

TEST_F(Report, ErrorImagesHaveAColourBar) {
  ASSERT_EQ(status_, 0);
  // Above the section's first error image.
  for (const auto& [id, first_error] :
       {std::pair<std::string, std::string>{"errors", "<img src=\"error-"},
        {"foliage", "-error-"}}) {
    const std::string section = section_of(html_, id);
    const std::size_t bar = section.find("<svg class=\"colorbar\"");
    ASSERT_NE(bar, std::string::npos) << id;
    EXPECT_LT(bar, section.find(first_error)) << id;
    EXPECT_NE(section.find("data-value=\"-0.5\"", bar), std::string::npos) << id;
    EXPECT_NE(section.find("data-value=\"0.5\"", bar), std::string::npos) << id;
  }
}

// At light size 0 every technique measures about the same RMSE; the page
// says why, and its numbers are the hard row's of the light-size table.
TEST_F(Report, TheErrorAtLightSizeZeroIsExplainedByItsNumbers) {
  ASSERT_EQ(status_, 0);
  const std::string sweeps = section_of(html_, "sweeps");
  const std::regex why_re(
      R"re(disagrees with the traced rays on (\d+) of the (\d+) pixels compared \([0-9.]+ %\), ([^<]*?) within 2 pixels of the reference's shadow edge[^<]*sqrt\(([0-9.]+)\) = ([0-9.]+))re");
  std::smatch why;
  ASSERT_TRUE(std::regex_search(sweeps, why, why_re)) << sweeps;
  const double wrong = std::stod(why[1].str()), compared = std::stod(why[2].str());
  EXPECT_GT(wrong, 0.0);
  EXPECT_NEAR(std::stod(why[5].str()), std::sqrt(wrong / compared), 1e-4);
  // Measured: every wrong pixel is at an edge (the sentence says how many).
  EXPECT_EQ(why[3].str(), "every one of them") << why[3].str();
  const Table table = tables_of(sweeps).back();
  const int hard = column_of(table, "RMSE hard (no penumbra)");
  ASSERT_GE(hard, 0);
  const auto* zero = row_of(table, "0.00");
  ASSERT_NE(zero, nullptr);
  // The hard shadow's RMSE is that square root: binary errors of 1, nearly
  // all of its error (a few pixels may be off by less than a half).
  EXPECT_NEAR(number((*zero)[static_cast<std::size_t>(hard)]), std::stod(why[5].str()), 0.003);
}

// The sun's texels per pixel: a table row and a plotted series per
// shadow-map layout, each point a median over a band of distances; its
// image is written.
TEST_F(Report, TexelDensityOfEachLayoutAgainstDistance) {
  const std::string section = section_of(html_, "density");
  ASSERT_FALSE(section.empty());
  const Table table = tables_of(section).front();
  const int share = column_of(table, "at least 1 texel");
  ASSERT_GE(share, 0);
  ASSERT_EQ(table.size(), 3u) << "two layouts: the cascades, virtual maps";
  EXPECT_NE(table[1][0].find("cascades"), std::string::npos);
  EXPECT_NE(table[2][0].find("virtual"), std::string::npos);
  const double percent = std::stod(table[1][static_cast<std::size_t>(share)]);
  EXPECT_GT(percent, 0.0);
  EXPECT_LE(percent, 100.0);
  // Virtual maps give (almost) every pixel a texel of its own; the
  // remainder are faces turned along the light's rays.
  EXPECT_GE(std::stod(table[2][static_cast<std::size_t>(share)]), 95.0);
  const std::vector<Plot> plots = plots_of(section);
  ASSERT_EQ(plots.size(), 1u);
  std::map<std::string, std::vector<PlotPoint>> series;
  for (const PlotPoint& p : plots.front().points) series[p.series].push_back(p);
  ASSERT_EQ(series.size(), 3u) << "both layouts and the one-texel line, no empty series";
  for (std::size_t row : {1u, 2u}) {
    const std::vector<PlotPoint>& layout = series[table[row][0]];
    ASSERT_GE(layout.size(), 4u) << table[row][0];
    for (std::size_t i = 0; i < layout.size(); ++i) {
      EXPECT_GT(layout[i].y, 0.0);
      if (row == 2) {
        EXPECT_GE(layout[i].y, 1.0) << "virtual maps' median at every distance";
      }
      if (i > 0) {
        EXPECT_GT(layout[i].x, layout[i - 1].x) << "in order of distance";
      }
    }
  }
  for (const PlotPoint& p : series["one texel per pixel"]) EXPECT_EQ(p.y, 1.0);
  // Each layout's density and hard shadow.
  for (int i = 1; i < 4; ++i) {
    EXPECT_TRUE(fs::exists(dir_ / ("texel-density-" + std::to_string(i) + ".png"))) << i;
  }
  EXPECT_TRUE(fs::exists(dir_ / "texel-density-0.png"));
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
