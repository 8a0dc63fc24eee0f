#include "report/study_run.hpp"

#include <vector>

#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

std::vector<int> swept_widths(bool quick) {
  return quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32};
}

std::vector<Technique> width_swept_techniques(bool quick) {
  return quick ? std::vector<Technique>{Technique::Msm}
               : std::vector<Technique>{Technique::Msm, Technique::Vsm, Technique::Esm,
                                        Technique::Msm16};
}

}  // namespace

// The spot light's traced reference (the first section to ask for it), a
// figure and a measurement per technique and width, then the light sizes.
int Study::sweeps_items() const {
  const auto widths = static_cast<int>(swept_widths(options_.quick).size());
  const auto techniques = static_cast<int>(width_swept_techniques(options_.quick).size());
  return 1 + 2 * widths * techniques + light_size_items();
}

void Study::sweeps_section(HtmlPage& page) {
  section(page, "sweeps", "4. From anti-aliased to soft: filter widths and light sizes");
  page.paragraph(
      "W = 1 or 2 only anti-aliases the edge; W = 16 and 32 simulate a wide light. A fixed "
      "filter widens every penumbra alike, contact shadows included; PCSS widens them with "
      "the blocker-receiver distance (sharp at the box's foot, wide under the high slab).");
  // Every frame of the sweeps under the measured light alone (as section 5's):
  // its shadow is what they measure.
  const LightAlone& alone = measured_light_alone();
  const ScopedLights lit(renderer_, alone.lights);
  if (alone.choice != options_.light_choice) {
    page.paragraph("The scene under its " + alone.choice + " light alone (--light " + alone.choice +
                   "), whose shadow the numbers measure.");
  }
  const TracedReference* traced = base_traced();
  const std::vector<int> widths = swept_widths(options_.quick);
  const std::vector<Technique> swept = width_swept_techniques(options_.quick);
  LinePlot width_plot{.title = "Error against filter width",
                      .x = {"Gaussian radius W (shadow-map texels)", true},
                      .y = {kRmseLabel, false},
                      .series = {},
                      .highlight_name = {}};
  std::vector<std::vector<std::string>> width_rows = {{"technique", "W (texels)", "RMSE"}};
  std::vector<std::vector<HtmlFigure>> width_figures;
  for (Technique t : swept) {
    PlotSeries series{.name = name_of(t), .points = {}, .lines = true};
    std::vector<HtmlFigure> figures;
    for (int w : widths) {
      ShadowSettings s = with(t);
      s.blur = w;
      std::optional<Image> image;
      figures.push_back(figure(renderer_, alone.choice,
                               "sweep-" + name_of(t) + "-w" + std::to_string(w) + ".png",
                               name_of(t) + ", W = " + std::to_string(w), base_render_, s, &image));
      step();
      if (traced && image) {
        const double rmse = compare_shadow(*image, traced->image).rmse;
        series.points.push_back({.x = double(w), .y = rmse, .label = {}, .highlighted = false});
        width_rows.push_back({name_of(t), std::to_string(w), fixed(rmse, 4)});
      }
    }
    width_plot.series.push_back(series);
    width_figures.push_back(figures);
  }
  page.paragraph(
      "The error of each width against the traced reference of the spot light (light size " +
      fixed(base_shadow_.light_size, 2) +
      "): too small a W leaves the edge hard where the true penumbra is wide, too large a W "
      "blurs contact shadows that should stay sharp.");
  page.plot(svg_line_plot(width_plot), width_rows);
  for (std::size_t i = 0; i < swept.size(); ++i) {
    page.heading(name_of(swept[i]) + ", Gaussian of radius W", 3);
    page.figures(width_figures[i]);
  }
  light_size_sweep(page);
}

}  // namespace penumbra
