// The report's SVG plots: ticks cover the data with round steps, every value
// drawn carries its numbers, and each sits where its axes put it.
#include "report/svg_plot.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace {

using penumbra::LinePlot;
using penumbra::log2_ticks;
using penumbra::nice_ticks;

TEST(SvgPlot, NiceTicksCoverTheRangeWithRoundSteps) {
  const std::vector<double> t = nice_ticks(0.0, 0.0123, 6);
  ASSERT_GE(t.size(), 3u);
  EXPECT_LE(t.front(), 0.0);
  EXPECT_GE(t.back(), 0.0123);
  EXPECT_LE(t.size(), 8u);
  const double step = t[1] - t[0];
  EXPECT_NEAR(step, 0.005, 1e-12);  // 1, 2 or 5 times a power of ten
  const std::vector<double> c = nice_ticks(10.0, 87.0, 7);
  EXPECT_EQ(c.front(), 0.0);
  EXPECT_EQ(c.back(), 100.0);
  EXPECT_NEAR(c[1] - c[0], 20.0, 1e-9);
}

TEST(SvgPlot, Log2TicksArePowersOfTwo) {
  EXPECT_EQ(log2_ticks(1.0, 32.0, 8), (std::vector<double>{1, 2, 4, 8, 16, 32}));
  EXPECT_EQ(log2_ticks(3.0, 20.0, 8), (std::vector<double>{2, 4, 8, 16, 32}));
  const std::vector<double> wide = log2_ticks(1.0, 4096.0, 5);
  EXPECT_LE(wide.size(), 5u);
  EXPECT_EQ(wide.front(), 1.0);
  EXPECT_GE(wide.back(), 4096.0);
}

TEST(SvgPlot, PointsCarryTheirDataAndSitOnTheirAxes) {
  LinePlot plot;
  plot.title = "error & width";
  plot.x = {"W (texels)", true};
  plot.y = {"RMSE", false};
  plot.series = {{"msm", {{1, 0.02, ""}, {4, 0.01, "", true}, {32, 0.04, ""}}, true},
                 {"vsm <sat>", {{2, 0.03, "x", true}}, false},
                 {"empty", {}, true}};
  plot.highlight_name = "front";
  const std::string svg = penumbra::svg_line_plot(plot);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("error &amp; width"), std::string::npos) << "text is escaped";
  EXPECT_NE(svg.find("vsm &lt;sat&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("empty"), std::string::npos) << "a series without points has no legend";
  EXPECT_NE(svg.find("(log scale)"), std::string::npos);
  EXPECT_NE(svg.find("class=\"highlight\""), std::string::npos);

  // Each point: its data, and the first coordinate of its marker path (a
  // circle starts r = 4 left of its centre).
  const std::regex point_re(
      R"re(class="point" data-series="msm" data-x="([^"]+)" data-y="([^"]+)" d="M([0-9.]+),([0-9.]+))re");
  std::vector<std::array<double, 4>> points;
  for (std::sregex_iterator it(svg.begin(), svg.end(), point_re), end; it != end; ++it) {
    points.push_back(
        {std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]) + 4.0, std::stod((*it)[4])});
  }
  ASSERT_EQ(points.size(), 3u);
  EXPECT_EQ(points[0][0], 1.0);
  EXPECT_EQ(points[1][1], 0.01);
  // Log x: W = 4 is 2/5 of the way from W = 1 to W = 32.
  const double left = points[0][2], right = points[2][2];
  EXPECT_NEAR((points[1][2] - left) / (right - left), 0.4, 1e-3);
  // Linear y from 0: 0.01 is a quarter of the way to 0.04 above the axis.
  const double zero = points[0][3] + (points[0][3] - points[2][3]) * 0.02 / 0.02;
  EXPECT_NEAR((zero - points[1][3]) / (zero - points[2][3]), 0.25, 1e-3);
}

// The labels of points that crowd together (the quality-against-cost
// plot's evsm4, msm and msm16) do not overlap one another, and a series
// drawn without lines has none in its legend.
TEST(SvgPlot, CrowdedLabelsDoNotOverlapAndUnjoinedPointsHaveNoLegendLine) {
  LinePlot plot;
  plot.title = "cost";
  plot.x = {"ms", false};
  plot.y = {"RMSE", false};
  plot.series = {{"technique",
                  {{10.0, 0.050, "hard"},
                   {30.0, 0.0300, "msm"},
                   {30.3, 0.0302, "msm16"},
                   {30.6, 0.0299, "evsm4"},
                   {30.1, 0.0305, "evsm2"},
                   {50.0, 0.020, "pcss"}},
                  false},
                 {"joined", {{10.0, 0.01, ""}, {50.0, 0.02, ""}}, true}};
  const std::string svg = penumbra::svg_line_plot(plot);
  // The labels' boxes, estimated as the plot places them: 10 px text, at
  // most 6 px a character.
  const std::regex label_re(
      R"re(<text x="([0-9.]+)" y="([0-9.]+)" class="label" text-anchor="(\w+)"[^>]*>([^<]+)</text>)re");
  struct Box {
    double x0, y0, x1, y1;
    std::string text;
  };
  std::vector<Box> boxes;
  for (std::sregex_iterator it(svg.begin(), svg.end(), label_re), end; it != end; ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    const std::string anchor = (*it)[3], text = (*it)[4];
    const double w = 5.8 * static_cast<double>(text.size());
    const double x0 = anchor == "start" ? x : anchor == "end" ? x - w : x - w / 2;
    boxes.push_back({x0, y - 8.0, x0 + w, y + 2.5, text});
  }
  ASSERT_EQ(boxes.size(), 6u) << svg;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Box &a = boxes[i], &b = boxes[j];
      const bool apart = a.x1 <= b.x0 || b.x1 <= a.x0 || a.y1 <= b.y0 || b.y1 <= a.y0;
      EXPECT_TRUE(apart) << a.text << " overlaps " << b.text;
    }
  }
  // One legend line: the joined series'.
  std::size_t lines = 0;
  for (std::size_t at = svg.find("class=\"legend-line\""); at != std::string::npos;
       at = svg.find("class=\"legend-line\"", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, 1u);
}

// The error images' colour bar runs from the map's blue end to its red
// end, its ticks at -range, 0 and +range.
TEST(SvgPlot, ErrorColourBarShowsTheMapAndItsRange) {
  const std::string svg = penumbra::svg_error_color_bar(0.5f, "technique - reference");
  EXPECT_NE(svg.find("technique - reference"), std::string::npos);
  const std::regex fill_re(R"re(fill="(#[0-9a-f]{6})")re");
  std::vector<std::string> fills;
  for (std::sregex_iterator it(svg.begin(), svg.end(), fill_re), end; it != end; ++it) {
    fills.push_back((*it)[1]);
  }
  ASSERT_GE(fills.size(), 64u);
  // Moreland's ends: blue (59, 76, 192) and red (180, 4, 38), near enough
  // at the outermost steps.
  const auto channel = [](const std::string& hex, int c) {
    return std::stoi(hex.substr(1 + 2 * c, 2), nullptr, 16);
  };
  EXPECT_GT(channel(fills.front(), 2), 150);
  EXPECT_LT(channel(fills.front(), 0), 100);
  EXPECT_GT(channel(fills[63], 0), 150);
  EXPECT_LT(channel(fills[63], 2), 80);
  for (const char* tick : {"data-value=\"-0.5\"", "data-value=\"0\"", "data-value=\"0.5\""}) {
    EXPECT_NE(svg.find(tick), std::string::npos) << tick;
  }
  EXPECT_NE(svg.find("not compared"), std::string::npos);
}

TEST(SvgPlot, StackedBarsCarryEachSegment) {
  penumbra::StackedBars bars;
  bars.title = "bytes";
  bars.value_label = "bytes per texel";
  bars.categories = {"vsm", "msm"};
  bars.stack_names = {"resolve", "blur"};
  bars.values = {{12.0, 16.0}, {20.0, 0.0}};
  const std::string svg = penumbra::svg_stacked_bars(bars);
  const std::regex bar_re(
      R"re(class="bar" data-category="([^"]+)" data-series="([^"]+)" data-value="([^"]+)" x="([^"]+)" y="[^"]+" width="([^"]+)")re");
  std::vector<std::smatch> found;
  for (std::sregex_iterator it(svg.begin(), svg.end(), bar_re), end; it != end; ++it) {
    found.push_back(*it);
  }
  ASSERT_EQ(found.size(), 3u) << "a zero segment is not drawn";
  EXPECT_EQ(found[0][1].str(), "vsm");
  EXPECT_EQ(found[1][2].str(), "blur");
  EXPECT_EQ(std::stod(found[2][3]), 20.0);
  // Segments of a bar are end to end, widths in proportion to the values.
  EXPECT_NEAR(std::stod(found[0][4]) + std::stod(found[0][5]), std::stod(found[1][4]), 0.02);
  EXPECT_NEAR(std::stod(found[1][5]) / std::stod(found[0][5]), 16.0 / 12.0, 1e-3);
}

TEST(SvgPlot, PlotNumbersAreShort) {
  EXPECT_EQ(penumbra::plot_number(16.0), "16");
  EXPECT_EQ(penumbra::plot_number(0.00125), "0.00125");
  EXPECT_EQ(penumbra::plot_number(0.123456), "0.1235");
}

}  // namespace
