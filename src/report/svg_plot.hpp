#pragma once
// Plots for the report as inline SVG: no script, no fonts or files to
// load, readable in print (every series has its own marker shape and dash
// pattern as well as its colour). Each drawn value carries its data as
// attributes (data-series, data-x, data-y / data-value) so a reader, or a
// test, can get the numbers back from the picture.
#include <string>
#include <vector>

namespace penumbra {

struct PlotAxis {
  std::string label;  // with its unit: "RMSE against the traced reference"
  bool log2 = false;  // a base-2 logarithmic axis (filter widths 1..32)
};

struct PlotPoint {
  double x = 0.0, y = 0.0;
  std::string label;         // written beside the point when not empty
  bool highlighted = false;  // drawn filled and joined by the highlight line
};

struct PlotSeries {
  std::string name;
  std::vector<PlotPoint> points;
  bool lines = true;  // join the points in order
};

struct LinePlot {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  // Legend entry of the line through the highlighted points (in x order),
  // e.g. "Pareto front"; no line when empty.
  std::string highlight_name;
};

// An <svg> element of the plot, sized by its viewBox to scale with the page.
// Axes span the data (a linear y axis starts at 0 when the data are
// non-negative). A series with no points is left out of the legend.
std::string svg_line_plot(const LinePlot& plot);

struct StackedBars {
  std::string title;
  std::string value_label;                  // the bars' axis, with its unit
  std::vector<std::string> categories;      // one horizontal bar each
  std::vector<std::string> stack_names;     // the segments of every bar
  std::vector<std::vector<double>> values;  // [category][segment], >= 0
};

// Horizontal bars, one per category, of its segments end to end; each
// segment's value is written on the bar when it fits.
std::string svg_stacked_bars(const StackedBars& bars);

// The colour bar of the error images (reference/error_image.hpp): the
// diverging map from -range (technique too dark) to +range (too light),
// its ticks, and the grey of the pixels not compared; `what` names the
// difference ("technique - traced reference").
std::string svg_error_color_bar(float range, const std::string& what);

// Round tick values covering [low, high]: steps of 1, 2 or 5 times a power
// of ten, at most about `count` of them, the first <= low and the last >=
// high. low < high.
std::vector<double> nice_ticks(double low, double high, int count);

// Powers of two covering [low, high] (0 < low < high), every k-th one so
// there are at most `count`.
std::vector<double> log2_ticks(double low, double high, int count);

// A number as the plots and their tables write it: %.4g without trailing
// zeros ("0.00125", "16", "1.5e+03").
std::string plot_number(double value);

}  // namespace penumbra
