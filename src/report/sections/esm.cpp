#include "report/study_run.hpp"

#include <iterator>
#include <sstream>

#include "report/ranking.hpp"
#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

constexpr float kEsmExponents[] = {10.0f, 20.0f, 40.0f, 60.0f, 80.0f, kEsmMaxC};

struct EsmPoint {
  float c;
  ShadowMetrics m;
};

// What the sweep of c shows, its best c named only when no other c
// measures the same at the printed precision (a tie is called a tie).
std::string esm_discussion(const std::vector<EsmPoint>& points) {
  std::vector<double> mae;
  for (const EsmPoint& p : points) mae.push_back(p.m.mean_absolute_error);
  const std::vector<std::size_t> best = least_at_precision(mae, 4);
  std::vector<std::string> names;
  for (std::size_t i : best) names.push_back(fixed(points[i].c, 0));
  const auto& first = points.front().m;
  const auto& last = points.back().m;
  std::ostringstream out;
  out << "What c trades: the test exp(-c (z_f - z)) darkens a receiver only once it is "
         "several 1/c behind its occluder, so a small c leaves a lit band where shadows "
         "begin (light leaking near contact) and fades them; a large c makes the test sharp "
         "but also sharpens the filtered edge away from the reference. Here the mean error "
         "goes from "
      << fixed(first.mean_absolute_error, 4) << " at c = " << fixed(points.front().c, 0) << " to "
      << fixed(last.mean_absolute_error, 4) << " at c = " << fixed(points.back().c, 0)
      << ", and light leaking from " << fixed(100.0 * first.leak_fraction, 3) << " % to "
      << fixed(100.0 * last.leak_fraction, 3) << " % of the pixels. On this scene ";
  if (names.size() == 1) {
    out << "c = " << names.front() << " measures the least mean error, "
        << fixed(mae[best.front()], 4) << ".";
  } else {
    out << "c = " << join_names(names) << " tie for the least mean error, "
        << fixed(mae[best.front()], 4) << " at this precision.";
  }
  return out.str();
}

}  // namespace

// A figure and a measurement per exponent.
int Study::esm_items() const {
  return 2 * static_cast<int>(std::size(kEsmExponents));
}

void Study::esm_section(HtmlPage& page) {
  section(page, "esm", "5. The ESM exponent c");
  const std::vector<float> cs(std::begin(kEsmExponents), std::end(kEsmExponents));
  std::vector<HtmlFigure> figures;
  std::vector<std::vector<std::string>> rows = {
      {"c", "mean abs. error", "light leaking", "over-darkening", "max error"}};
  std::vector<EsmPoint> points;
  // The measured light alone, as in section 4.
  const LightAlone& alone = measured_light_alone();
  const ScopedLights lit(renderer_, alone.lights);
  for (float c : cs) {
    ShadowSettings s = with(Technique::Esm);
    s.esm_c = c;
    std::optional<Image> image;
    figures.push_back(figure(renderer_, alone.choice, "esm-c" + fixed(c, 0) + ".png",
                             "esm, c = " + fixed(c, 0), base_render_, s, &image));
    step();
    if (auto m = measure_against_filtered(s, image)) {
      points.push_back({c, *m});
      rows.push_back({fixed(c, 0), fixed(m->mean_absolute_error, 4),
                      fixed(100.0 * m->leak_fraction, 3) + " %",
                      fixed(100.0 * m->over_dark_fraction, 3) + " %", fixed(m->max_error, 3)});
    }
  }
  page.paragraph(
      "The map stores exp(c (z - 1)), in (0, 1] for every c, so it cannot overflow; c is "
      "capped at " +
      fixed(kEsmMaxC, 0) +
      " where exp(-c) would leave the normal float range. Measured on the spot light's shadow "
      "factor (W = 4) against the filtered hard reference; light leaking counts pixels the "
      "reference has in shadow (< 0.1) that the technique lights (> 0.3), over-darkening "
      "the reverse (reference > 0.9, technique < 0.7)." +
      (alone.choice != options_.light_choice ? " The images: the scene under its " + alone.choice +
                                                   " light alone (--light " + alone.choice + ")."
                                             : std::string()));
  page.table(rows);
  LinePlot plot{.title = "ESM: leaking and over-darkening against c",
                .x = {"ESM exponent c", false},
                .y = {"pixels compared (%)", false},
                .series = {{"light leaking", {}, true}, {"over-darkening", {}, true}},
                .highlight_name = {}};
  std::vector<std::vector<std::string>> data = {{"c", "light leaking (%)", "over-darkening (%)"}};
  for (const EsmPoint& p : points) {
    plot.series[0].points.push_back({p.c, 100.0 * p.m.leak_fraction, "", false});
    plot.series[1].points.push_back({p.c, 100.0 * p.m.over_dark_fraction, "", false});
    data.push_back({fixed(p.c, 0), fixed(100.0 * p.m.leak_fraction, 3),
                    fixed(100.0 * p.m.over_dark_fraction, 3)});
  }
  page.plot(svg_line_plot(plot), data);
  if (!points.empty()) page.paragraph(esm_discussion(points));
  page.figures(figures);
}

}  // namespace penumbra
