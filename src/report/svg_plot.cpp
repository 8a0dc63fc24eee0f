#include "report/svg_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "reference/error_image.hpp"
#include "report/html_page.hpp"

namespace penumbra {

namespace {

// Okabe & Ito's colour-blind-safe palette (yellow, weak on white paper,
// left out); print tells the series apart by marker and dash as well.
constexpr std::array<const char*, 7> kColors = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                "#e69f00", "#56b4e9", "#000000"};
constexpr std::array<const char*, 5> kDashes = {"", "6 3", "2 3", "8 3 2 3", "4 4"};
constexpr int kMarkerShapes = 6;

// The plot area inside the 640-wide viewBox; the legend sits to its right.
constexpr double kWidth = 640.0;
constexpr double kLeft = 72.0, kRight = 470.0, kTop = 36.0;
constexpr double kLegendX = 486.0;
constexpr double kLineBottom = 300.0;  // the line plot's area ends here

std::string num(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// Full precision for the data attributes: the numbers the plot was made of.
std::string data_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// A closed path of marker `shape` (circle, square, triangle, diamond,
// inverted triangle, plus) of radius r around (x, y).
std::string marker_path(int shape, double x, double y, double r) {
  const auto p = [](double px, double py) { return num(px) + "," + num(py); };
  switch (shape % kMarkerShapes) {
    case 0:
      return "M" + p(x - r, y) + "a" + num(r) + "," + num(r) + " 0 1,0 " + num(2 * r) + ",0a" +
             num(r) + "," + num(r) + " 0 1,0 " + num(-2 * r) + ",0Z";
    case 1: {
      const double s = r * 0.85;
      return "M" + p(x - s, y - s) + "L" + p(x + s, y - s) + "L" + p(x + s, y + s) + "L" +
             p(x - s, y + s) + "Z";
    }
    case 2:
      return "M" + p(x, y - r * 1.1) + "L" + p(x + r, y + r * 0.8) + "L" + p(x - r, y + r * 0.8) +
             "Z";
    case 3:
      return "M" + p(x, y - r * 1.2) + "L" + p(x + r, y) + "L" + p(x, y + r * 1.2) + "L" +
             p(x - r, y) + "Z";
    case 4:
      return "M" + p(x, y + r * 1.1) + "L" + p(x + r, y - r * 0.8) + "L" + p(x - r, y - r * 0.8) +
             "Z";
    default: {
      const double t = r * 0.35;
      return "M" + p(x - t, y - r) + "L" + p(x + t, y - r) + "L" + p(x + t, y - t) + "L" +
             p(x + r, y - t) + "L" + p(x + r, y + t) + "L" + p(x + t, y + t) + "L" +
             p(x + t, y + r) + "L" + p(x - t, y + r) + "L" + p(x - t, y + t) + "L" +
             p(x - r, y + t) + "L" + p(x - r, y - t) + "L" + p(x - t, y - t) + "Z";
    }
  }
}

std::string text(double x, double y, const std::string& content, const std::string& attributes) {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" " + attributes + ">" +
         html_escape(content) + "</text>\n";
}

std::string line(double x0, double y0, double x1, double y1, const std::string& attributes) {
  return "<line x1=\"" + num(x0) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(x1) + "\" y2=\"" +
         num(y1) + "\" " + attributes + "/>\n";
}

std::string svg_open(double height, const std::string& title) {
  return "<svg class=\"plot\" viewBox=\"0 0 " + num(kWidth) + " " + num(height) +
         "\" role=\"img\" aria-label=\"" + html_escape(title) +
         "\" font-family=\"sans-serif\" font-size=\"11\">\n<title>" + html_escape(title) +
         "</title>\n" + text(kLeft, 20, title, "font-size=\"14\" font-weight=\"600\"");
}

// One axis: its range in axis units (log2 of the value on a log axis) and
// its ticks as values.
struct Axis {
  bool log2 = false;
  double low = 0.0, high = 1.0;
  std::vector<double> ticks;
  [[nodiscard]] double t(double value) const {
    const double u = log2 ? std::log2(value) : value;
    return (u - low) / (high - low);
  }
};

Axis make_axis(const PlotAxis& axis, double low, double high, bool from_zero, int count) {
  Axis a;
  a.log2 = axis.log2;
  if (!(low <= high)) low = 0.0, high = 1.0;  // no data
  if (axis.log2) {
    low = std::max(low, std::numeric_limits<double>::min());
    high = std::max(high, low);
    if (high == low) low /= 2.0, high *= 2.0;
    a.ticks = log2_ticks(low, high, count);
    a.low = std::log2(a.ticks.front());
    a.high = std::log2(a.ticks.back());
    return a;
  }
  if (from_zero && low >= 0.0) low = 0.0;
  if (high == low) high = low + (low == 0.0 ? 1.0 : std::abs(low));
  a.ticks = nice_ticks(low, high, count);
  a.low = a.ticks.front();
  a.high = a.ticks.back();
  return a;
}

// A label's box in the viewBox, estimated from its length (11-px-high
// sans-serif text of font-size 10 averages under 6 px a character).
struct LabelBox {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  [[nodiscard]] double overlap(const LabelBox& o) const {
    const double w = std::min(x1, o.x1) - std::max(x0, o.x0);
    const double h = std::min(y1, o.y1) - std::max(y0, o.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
  }
};

struct PlacedLabel {
  double x = 0, y = 0;  // the text's anchor point (baseline)
  const char* anchor = "start";
  bool leader = false;  // moved away from its point: joined to it by a line
};

// Places each point's label beside it where it overlaps no other label,
// no marker and stays inside the plot area: the nearest of a few positions
// around the point, then further ones with a leader line; failing all,
// the one that overlaps least. `points` are in viewBox coordinates.
std::vector<PlacedLabel> place_labels(const std::vector<std::pair<double, double>>& points,
                                      const std::vector<std::string>& labels) {
  constexpr double kCharWidth = 5.8, kAscent = 8.0, kDescent = 2.5, kMarker = 5.0;
  struct Candidate {
    double dx, dy;
    const char* anchor;
  };
  std::vector<Candidate> candidates = {{6, -6, "start"}, {6, 13, "start"},  {-6, -6, "end"},
                                       {-6, 13, "end"},  {0, -9, "middle"}, {0, 17, "middle"}};
  for (double step : {12.0, 24.0, 36.0}) {
    for (const Candidate& c : std::vector<Candidate>(candidates.begin(), candidates.begin() + 6)) {
      candidates.push_back({c.dx + (c.dx > 0   ? step
                                    : c.dx < 0 ? -step
                                               : 0),
                            c.dy + (c.dy < 0 ? -step : step), c.anchor});
    }
  }
  std::vector<LabelBox> taken;
  for (const auto& [x, y] : points) {
    taken.push_back({x - kMarker, y - kMarker, x + kMarker, y + kMarker});
  }
  std::vector<PlacedLabel> placed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (labels[i].empty()) continue;
    const double width = kCharWidth * static_cast<double>(labels[i].size());
    double least = std::numeric_limits<double>::infinity();
    LabelBox chosen;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const Candidate& k = candidates[c];
      const double x = points[i].first + k.dx, y = points[i].second + k.dy;
      const double x0 = k.anchor[0] == 's' ? x : k.anchor[0] == 'e' ? x - width : x - width / 2;
      const LabelBox box{x0, y - kAscent, x0 + width, y + kDescent};
      double cost = 0.0;
      for (const LabelBox& t : taken) cost += t.overlap(box);
      // Outside the plot area counts as overlapping.
      const LabelBox area{kLeft, kTop, kRight, kLineBottom};
      cost += (box.x1 - box.x0) * (box.y1 - box.y0) - area.overlap(box);
      if (cost < least - 1e-9) {
        least = cost;
        chosen = box;
        placed[i] = {x, y, k.anchor, c >= 6};
      }
      if (cost == 0.0) break;
    }
    taken.push_back(chosen);
  }
  return placed;
}

}  // namespace

std::string plot_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

std::vector<double> nice_ticks(double low, double high, int count) {
  const double raw = (high - low) / std::max(1, count - 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  const double first = std::floor(low / step + 1e-9);
  const double last = std::ceil(high / step - 1e-9);
  for (double k = first; k <= last; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  }
  return ticks;
}

std::vector<double> log2_ticks(double low, double high, int count) {
  const int first = static_cast<int>(std::floor(std::log2(low) + 1e-9));
  const int last = static_cast<int>(std::ceil(std::log2(high) - 1e-9));
  const int every = std::max(1, (last - first + count - 1) / std::max(1, count - 1));
  std::vector<double> ticks;
  int k = first;
  for (; k < last; k += every) ticks.push_back(std::exp2(k));
  ticks.push_back(std::exp2(k));
  return ticks;
}

std::string svg_line_plot(const LinePlot& plot) {
  constexpr double kBottom = kLineBottom, kHeight = 346.0;
  double x_low = std::numeric_limits<double>::infinity(), x_high = -x_low;
  double y_low = x_low, y_high = -x_low;
  for (const PlotSeries& s : plot.series) {
    for (const PlotPoint& p : s.points) {
      x_low = std::min(x_low, p.x), x_high = std::max(x_high, p.x);
      y_low = std::min(y_low, p.y), y_high = std::max(y_high, p.y);
    }
  }
  const Axis ax = make_axis(plot.x, x_low, x_high, false, 7);
  const Axis ay = make_axis(plot.y, y_low, y_high, true, 6);
  const auto px = [&](double v) { return kLeft + ax.t(v) * (kRight - kLeft); };
  const auto py = [&](double v) { return kBottom - ay.t(v) * (kBottom - kTop); };

  std::string svg = svg_open(kHeight, plot.title);
  // Grid, ticks and their labels.
  for (double v : ax.ticks) {
    svg += line(px(v), kTop, px(v), kBottom, "stroke=\"#e4e4e4\"");
    svg += text(px(v), kBottom + 15, plot_number(v), "text-anchor=\"middle\"");
  }
  for (double v : ay.ticks) {
    svg += line(kLeft, py(v), kRight, py(v), "stroke=\"#e4e4e4\"");
    svg += text(kLeft - 6, py(v) + 4, plot_number(v), "text-anchor=\"end\"");
  }
  svg += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(kTop) + "\" width=\"" + num(kRight - kLeft) +
         "\" height=\"" + num(kBottom - kTop) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  svg +=
      text((kLeft + kRight) / 2, kBottom + 34, plot.x.label + (plot.x.log2 ? " (log scale)" : ""),
           "text-anchor=\"middle\" font-size=\"12\"");
  svg += text(0, 0, plot.y.label,
              "text-anchor=\"middle\" font-size=\"12\" transform=\"translate(16 " +
                  num((kTop + kBottom) / 2) + ") rotate(-90)\"");

  const bool highlighting = !plot.highlight_name.empty();
  if (highlighting) {
    std::vector<PlotPoint> front;
    for (const PlotSeries& s : plot.series) {
      for (const PlotPoint& p : s.points) {
        if (p.highlighted) front.push_back(p);
      }
    }
    std::sort(front.begin(), front.end(),
              [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
    if (front.size() > 1) {
      std::string points;
      for (const PlotPoint& p : front) points += num(px(p.x)) + "," + num(py(p.y)) + " ";
      svg += "<polyline class=\"highlight\" points=\"" + points +
             "\" fill=\"none\" stroke=\"#888\" stroke-width=\"6\" stroke-opacity=\"0.35\" "
             "stroke-linejoin=\"round\"/>\n";
    }
  }

  // Every point's label placed clear of the others, all series together.
  std::vector<std::pair<double, double>> positions;
  std::vector<std::string> labels;
  for (const PlotSeries& s : plot.series) {
    for (const PlotPoint& p : s.points) {
      positions.emplace_back(px(p.x), py(p.y));
      labels.push_back(p.label);
    }
  }
  const std::vector<PlacedLabel> placed = place_labels(positions, labels);
  std::size_t point_index = 0;

  int legend_row = 0;
  const auto legend_y = [&] { return kTop + 8 + 18 * legend_row++; };
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    if (s.points.empty()) continue;
    const std::string color = kColors[i % kColors.size()];
    const std::string dash = kDashes[i % kDashes.size()];
    const std::string dash_attribute =
        dash.empty() ? "" : " stroke-dasharray=\"" + std::string(dash) + "\"";
    svg += "<g class=\"series\" data-series=\"" + html_escape(s.name) + "\">\n";
    if (s.lines && s.points.size() > 1) {
      std::string points;
      for (const PlotPoint& p : s.points) points += num(px(p.x)) + "," + num(py(p.y)) + " ";
      svg += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + color +
             "\" stroke-width=\"1.6\"" + dash_attribute + "/>\n";
    }
    for (const PlotPoint& p : s.points) {
      const bool filled = !highlighting || p.highlighted;
      svg += "<path class=\"point\" data-series=\"" + html_escape(s.name) + "\" data-x=\"" +
             data_number(p.x) + "\" data-y=\"" + data_number(p.y) + "\" d=\"" +
             marker_path(static_cast<int>(i), px(p.x), py(p.y), 4.0) + "\" fill=\"" +
             (filled ? color : std::string("#fff")) + "\" stroke=\"" + color +
             "\" stroke-width=\"1.4\"><title>" +
             html_escape(s.name + (p.label.empty() ? "" : " " + p.label) + ": " + plot_number(p.x) +
                         ", " + plot_number(p.y)) +
             "</title></path>\n";
      const PlacedLabel& l = placed[point_index++];
      if (!p.label.empty()) {
        if (l.leader) {
          svg += line(px(p.x), py(p.y), l.x, l.y - 3, "stroke=\"#999\" stroke-width=\"0.8\"");
        }
        svg += text(l.x, l.y, p.label,
                    "class=\"label\" text-anchor=\"" + std::string(l.anchor) +
                        "\" font-size=\"10\" fill=\"#333\"");
      }
    }
    svg += "</g>\n";
    const double y = legend_y();
    // A line in the legend only for a series drawn with one.
    if (s.lines && s.points.size() > 1) {
      svg += line(
          kLegendX, y, kLegendX + 28, y,
          "class=\"legend-line\" stroke=\"" + color + "\" stroke-width=\"1.6\"" + dash_attribute);
    }
    svg += "<path d=\"" + marker_path(static_cast<int>(i), kLegendX + 14, y, 4.0) + "\" fill=\"" +
           color + "\" stroke=\"" + color + "\"/>\n";
    svg += text(kLegendX + 34, y + 4, s.name, "");
  }
  if (highlighting) {
    const double y = legend_y();
    svg += line(kLegendX, y, kLegendX + 28, y,
                "stroke=\"#888\" stroke-width=\"6\" stroke-opacity=\"0.35\"");
    svg += text(kLegendX + 34, y + 4, plot.highlight_name + " (filled)", "");
  }
  svg += "</svg>\n";
  return svg;
}

std::string svg_error_color_bar(float range, const std::string& what) {
  // Margins for the end ticks' labels ("-0.5 or more") either side.
  constexpr double kBarX = 50.0, kBarWidth = 380.0, kBarY = 24.0, kBarHeight = 16.0;
  const auto hex = [](glm::vec3 c) {
    char text[8];
    const auto byte = [](float v) {
      return static_cast<int>(std::lround(255.0 * std::clamp(double(v), 0.0, 1.0)));
    };
    std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return std::string(text);
  };
  std::string svg = "<svg class=\"colorbar\" viewBox=\"0 0 480 78\" role=\"img\" aria-label=\"" +
                    html_escape("colour bar: " + what) +
                    "\" font-family=\"sans-serif\" font-size=\"11\">\n" + "<title>" +
                    html_escape("colour bar: " + what) + "</title>\n";
  // The map in narrow steps (no gradient: its id would repeat when the
  // page shows the bar twice), each a 64th of the range.
  svg += text(kBarX, 14, what, "font-size=\"12\"");
  constexpr int kSteps = 64;
  for (int i = 0; i < kSteps; ++i) {
    const double t = -1.0 + 2.0 * (i + 0.5) / kSteps;
    const double w = kBarWidth / kSteps;
    svg += "<rect x=\"" + num(kBarX + w * i) + "\" y=\"" + num(kBarY) + "\" width=\"" +
           num(w + 0.3) + "\" height=\"" + num(kBarHeight) + "\" fill=\"" +
           hex(diverging_color(static_cast<float>(t))) + "\"/>";
  }
  svg += "\n<rect x=\"" + num(kBarX) + "\" y=\"" + num(kBarY) + "\" width=\"" + num(kBarWidth) +
         "\" height=\"" + num(kBarHeight) + "\" fill=\"none\" stroke=\"#444\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double value = range * (-1.0 + 0.5 * i);
    const double x = kBarX + kBarWidth * i / 4.0;
    svg += line(x, kBarY + kBarHeight, x, kBarY + kBarHeight + 4, "stroke=\"#444\"");
    svg += "<text class=\"tick\" data-value=\"" + data_number(value) + "\" x=\"" + num(x) +
           "\" y=\"" + num(kBarY + kBarHeight + 15) + "\" text-anchor=\"middle\">" +
           html_escape((value > 0 ? "+" : "") + plot_number(value) +
                       (i == 0   ? " or less"
                        : i == 4 ? " or more"
                                 : "")) +
           "</text>\n";
  }
  svg += text(kBarX, kBarY + kBarHeight + 30, "blue: too dark", "");
  svg += text(kBarX + kBarWidth, kBarY + kBarHeight + 30, "red: too light (leaks)",
              "text-anchor=\"end\"");
  svg += "<rect x=\"" + num(kBarX + kBarWidth / 2 - 58) + "\" y=\"" + num(kBarY + kBarHeight + 21) +
         "\" width=\"10\" height=\"10\" fill=\"" + hex(glm::vec3(kErrorImageBackground)) + "\"/>\n";
  svg += text(kBarX + kBarWidth / 2 - 44, kBarY + kBarHeight + 30, "not compared", "");
  svg += "</svg>\n";
  return svg;
}

std::string svg_stacked_bars(const StackedBars& bars) {
  constexpr double kBarLeft = 120.0, kRow = 22.0, kBar = 15.0;
  const double bottom = kTop + kRow * static_cast<double>(bars.categories.size()) + 4;
  const double height = std::max(bottom + 44, kTop + 18.0 * bars.stack_names.size() + 8);
  double high = 0.0;
  for (const auto& row : bars.values) {
    double sum = 0.0;
    for (double v : row) sum += v;
    high = std::max(high, sum);
  }
  const std::vector<double> ticks = nice_ticks(0.0, high > 0.0 ? high : 1.0, 6);
  const double scale = (kRight - kBarLeft) / ticks.back();

  std::string svg = svg_open(height, bars.title);
  for (double v : ticks) {
    const double x = kBarLeft + v * scale;
    svg += line(x, kTop, x, bottom, "stroke=\"#e4e4e4\"");
    svg += text(x, bottom + 15, plot_number(v), "text-anchor=\"middle\"");
  }
  svg += line(kBarLeft, kTop, kBarLeft, bottom, "stroke=\"#444\"");
  svg += line(kBarLeft, bottom, kRight, bottom, "stroke=\"#444\"");
  svg += text((kBarLeft + kRight) / 2, bottom + 34, bars.value_label,
              "text-anchor=\"middle\" font-size=\"12\"");
  for (std::size_t c = 0; c < bars.categories.size(); ++c) {
    const double y = kTop + kRow * static_cast<double>(c) + (kRow - kBar) / 2;
    svg += text(kBarLeft - 6, y + kBar - 4, bars.categories[c], "text-anchor=\"end\"");
    double x = kBarLeft;
    for (std::size_t s = 0; s < bars.stack_names.size() && c < bars.values.size(); ++s) {
      const double v = s < bars.values[c].size() ? bars.values[c][s] : 0.0;
      if (v <= 0.0) continue;
      const double w = v * scale;
      svg += "<rect class=\"bar\" data-category=\"" + html_escape(bars.categories[c]) +
             "\" data-series=\"" + html_escape(bars.stack_names[s]) + "\" data-value=\"" +
             data_number(v) + "\" x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) +
             "\" height=\"" + num(kBar) + "\" fill=\"" + kColors[s % kColors.size()] +
             "\" stroke=\"#fff\"><title>" +
             html_escape(bars.categories[c] + ", " + bars.stack_names[s] + ": " + plot_number(v)) +
             "</title></rect>\n";
      const std::string label = plot_number(v);
      if (w > 7.0 * static_cast<double>(label.size()) + 4) {
        svg += text(x + w / 2, y + kBar - 4, label, "text-anchor=\"middle\" fill=\"#fff\"");
      }
      x += w;
    }
  }
  for (std::size_t s = 0; s < bars.stack_names.size(); ++s) {
    const double y = kTop + 8 + 18 * static_cast<double>(s);
    svg += "<rect x=\"" + num(kLegendX) + "\" y=\"" + num(y - 6) +
           "\" width=\"22\" height=\"12\" fill=\"" + kColors[s % kColors.size()] + "\"/>\n";
    svg += text(kLegendX + 28, y + 4, bars.stack_names[s], "");
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace penumbra
