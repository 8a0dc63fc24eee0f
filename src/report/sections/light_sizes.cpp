#include "report/study_run.hpp"

#include <cmath>
#include <iterator>

#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

constexpr float kLightSizes[] = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f};
// pcss, vsm --soft, msm --soft and hard (light_size_sweep).
constexpr int kLightSizeTechniques = 4;

}  // namespace

// Per size: PCSS's figure, the size's traced reference, and a measurement
// per technique.
int Study::light_size_items() const {
  return static_cast<int>(std::size(kLightSizes)) * (2 + kLightSizeTechniques);
}

// PCSS at each light size, and every soft technique's error against the
// traced reference of the same light size (under the measured light alone,
// which sweeps_section sets).
void Study::light_size_sweep(HtmlPage& page) {
  page.heading("Light sizes", 3);
  const std::vector<float> sizes(std::begin(kLightSizes), std::end(kLightSizes));
  struct Soft {
    std::string name;
    ShadowSettings settings;
  };
  const std::vector<Soft> techniques = {{"pcss", with(Technique::Pcss)},
                                        {"vsm --soft", soft(Technique::Vsm)},
                                        {"msm --soft", soft(Technique::Msm)},
                                        {"hard (no penumbra)", with(Technique::Hard)}};
  static_assert(kLightSizeTechniques == 4, "one per entry above");
  LinePlot plot{.title = "Error against light size",
                .x = {"light size (source width, world units)", false},
                .y = {kRmseLabel, false},
                .series = {},
                .highlight_name = {}};
  for (const Soft& t : techniques) plot.series.push_back({t.name, {}, true});
  std::vector<std::vector<std::string>> rows = {{"light size"}};
  for (const Soft& t : techniques) rows.front().push_back("RMSE " + t.name);
  std::vector<HtmlFigure> figures;
  std::optional<EdgeErrors> point_light_errors;  // of hard shadows, at light size 0
  for (float size : sizes) {
    ShadowSettings pcss = with(Technique::Pcss);
    pcss.light_size = size;
    std::optional<Image> pcss_shadow;
    figures.push_back(figure(
        renderer_, measured_light_alone().choice, "sweep-pcss-light" + fixed(size, 2) + ".png",
        "pcss, light size " + fixed(size, 2), base_render_, pcss, &pcss_shadow));
    step();
    ShadowSettings light = base_shadow_;
    light.light_size = size;
    std::optional<TracedReference> sized;
    const TracedReference* traced = nullptr;
    if (size == base_shadow_.light_size) {
      traced = base_traced();
    } else {
      try {
        sized = trace(renderer_, base_render_, light);
        check_gl();
        traced = &*sized;
      } catch (const std::exception&) {
        ++failed_;
      }
    }
    std::vector<std::string> row = {fixed(size, 2)};
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      step();
      ShadowSettings s = techniques[i].settings;
      s.light_size = size;
      std::optional<Image> image = !traced  ? std::nullopt
                                   : i == 0 ? std::move(pcss_shadow)
                                            : shadow_image(s);
      if (!image) {
        row.push_back("failed");
        continue;
      }
      const double rmse = compare_shadow(*image, traced->image).rmse;
      row.push_back(fixed(rmse, 4));
      plot.series[i].points.push_back({size, rmse, "", false});
      if (size == 0.0f && techniques[i].settings.technique == Technique::Hard) {
        point_light_errors = edge_errors(*image, traced->image, 2);
      }
      if (size == sizes.back() && i + 1 < techniques.size()) {
        findings_.widest_light_rmse.push_back({techniques[i].name, rmse});
      }
    }
    rows.push_back(row);
  }
  findings_.widest_light_size = sizes.back();
  page.paragraph(
      "Each soft technique against the traced reference of the same light size (" +
      std::to_string(traced_samples()) +
      " rays per pixel): PCSS and the moment soft shadows (--soft, summed-area table) size "
      "each pixel's filter from a blocker search; hard shadows, which ignore the size, show "
      "what a penumbra is worth. The images: PCSS at each size.");
  if (point_light_errors) page.paragraph(point_light_floor(*point_light_errors));
  page.plot(svg_line_plot(plot), rows);
  page.figures(figures);
}

// Why every technique measures the same error at light size 0, from the
// hard shadow's pixels measured there.
std::string Study::point_light_floor(const EdgeErrors& e) const {
  const double share = e.compared > 0 ? double(e.wrong) / double(e.compared) : 0.0;
  return "Why every technique shows the same error at light size 0: the source is then a "
         "point, so the traced reference is 0 or 1 at every pixel, and the soft techniques' "
         "filters shrink to a single texel: each makes, in effect, the hard map's binary "
         "test. The hard test disagrees with the traced rays on " +
         std::to_string(e.wrong) + " of the " + std::to_string(e.compared) + " pixels compared (" +
         fixed(100.0 * share, 2) + " %), " +
         (e.near_edge == e.wrong ? std::string("every one of them")
                                 : std::to_string(e.near_edge) + " of them") +
         " within 2 pixels of the reference's shadow edge: the " +
         map_size_text(base_shadow_.map_size) +
         " map knows where a caster's edge lies only to within one of its texels, so along "
         "every shadow edge the pixels in a band up to a texel wide (projected onto the "
         "receiver) fall on the wrong side; a finer map narrows the band. Each such pixel is "
         "wrong by 1, "
         "so the RMSE is the square root of their share, sqrt(" +
         fixed(share, 4) + ") = " + fixed(std::sqrt(share), 4) +
         ", although the mean absolute error is only about " + fixed(share, 4) + ".";
}

}  // namespace penumbra
