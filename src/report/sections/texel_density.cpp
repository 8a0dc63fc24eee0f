#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "app/light_choice.hpp"
#include "reference/texel_density_stats.hpp"
#include "report/study_run.hpp"
#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

// A way to lay out a light's shadow maps, as the settings name it.
struct MapLayout {
  std::string name;  // the series' and the table's label
  ShadowSettings shadow;
};

// The layouts compared, each two figures (texel density, hard shadow),
// one table row and one plotted series: the directional light's cascades
// (the --cascades and --shadow-map-size the study runs at), and virtual
// maps in a page pool of --page-pool-mib (48 MiB by default: the memory of
// 3 cascades of 2048^2). Both draw the hard shadow, which reads each
// pixel's texel as the density view counts it.
std::vector<MapLayout> map_layouts(const ShadowSettings& base) {
  ShadowSettings cascades = base;
  cascades.technique = Technique::Hard;
  cascades.shadow_maps = ShadowMapKind::Cascades;
  ShadowSettings virtual_maps = cascades;
  virtual_maps.shadow_maps = ShadowMapKind::Virtual;
  return {
      {std::to_string(base.cascades) + " cascades of " + map_size_text(base.map_size), cascades},
      {"virtual maps, " + std::to_string(base.page_pool_mib) + " MiB page pool", virtual_maps}};
}

// The median density over distance bins of equal ratio (log-spaced), one
// point per non-empty bin at its pixels' median distance.
constexpr int kDistanceBins = 16;

std::vector<PlotPoint> density_over_distance(const Image& density, const SurfacePoints& surfaces,
                                             const glm::vec3& camera) {
  std::vector<std::pair<double, double>> samples;  // distance, density
  for (int y = 0; y < density.height; ++y) {
    for (int x = 0; x < density.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * density.width + x;
      const float* d = density.pixel(x, y);
      // Pixels no view covers (0) have no texel to plot on a log axis.
      if (d[3] < 0.5f || surfaces.covered[i] == 0 || !(d[0] > 0.0f)) continue;
      samples.emplace_back(glm::length(surfaces.position[i] - camera), d[0]);
    }
  }
  std::vector<PlotPoint> points;
  if (samples.empty()) return points;
  const auto [low, high] =
      std::minmax_element(samples.begin(), samples.end(),
                          [](const auto& a, const auto& b) { return a.first < b.first; });
  const double first = std::max(low->first, 1e-6), last = std::max(high->first, first * 1.0001);
  std::vector<std::vector<std::pair<double, double>>> bins(kDistanceBins);
  for (const auto& s : samples) {
    const double t = std::log(std::max(s.first, first) / first) / std::log(last / first);
    bins[std::min(static_cast<std::size_t>(t * kDistanceBins), bins.size() - 1)].push_back(s);
  }
  for (auto& bin : bins) {
    if (bin.empty()) continue;
    const std::size_t middle = (bin.size() - 1) / 2;
    std::vector<double> distances, densities;
    for (const auto& s : bin) {
      distances.push_back(s.first);
      densities.push_back(s.second);
    }
    std::nth_element(distances.begin(), distances.begin() + static_cast<std::ptrdiff_t>(middle),
                     distances.end());
    std::nth_element(densities.begin(), densities.begin() + static_cast<std::ptrdiff_t>(middle),
                     densities.end());
    points.push_back({distances[middle], densities[middle], "", false});
  }
  return points;
}

// Whether the study's --light leaves the scene a sun (none, or directional).
bool lit_by_the_sun(const std::string& light_choice) {
  return light_choice.empty() || light_choice == "directional";
}

}  // namespace

// Per layout: its texel-density image and its measurement.
int Study::texel_density_items() const {
  if (!lit_by_the_sun(options_.light_choice)) return 0;
  return 2 * static_cast<int>(map_layouts(base_shadow_).size());
}

// The sun's texels per pixel over the camera's view, per shadow-map layout:
// what decides whether a hard shadow far from the camera keeps its shape.
void Study::texel_density_section(HtmlPage& page) {
  section(page, "density", "10. Cascades or virtual maps: texels per pixel");
  page.paragraph(
      "Texel density: how many shadow-map texels fall into one pixel's footprint on the "
      "receiver (an area ratio; --view texel-density). Below 1 a texel spans several pixels "
      "and a hard shadow's edge shows the map's blocks; far above 1 texels are spent where "
      "no pixel sees them. Cascades spend a fixed budget on slices of the view: within a "
      "cascade the density grows with distance (a pixel covers more of the receiver, a texel "
      "does not), at each split it drops by the ratio of the two cascades' texel areas, so it "
      "is lowest where each cascade begins, and on receivers turned away from the light (a "
      "texel stretches over them). Virtual shadow maps (--shadow-maps virtual) give every pixel "
      "at least one texel: each pixel reads the clipmap level whose texel fits its footprint on "
      "the receiver, and the levels are made finer by the most half-level steps whose pages "
      "still fit the page pool, so they spend the cascades' memory where the camera looks. The "
      "scene under its sun alone "
      "(--light directional); false colour on a log scale: red 1/4 or less, orange 1/2, green "
      "1, cyan 2, blue 4 or more, black where no map covers the point; beside each, the hard "
      "shadow of the same frame.");
  if (!lit_by_the_sun(options_.light_choice)) {
    page.paragraph("This report was made with --light " + options_.light_choice +
                   ": without --light, or with --light directional, this section measures the "
                   "sun's maps.");
    return;
  }
  struct RestoreLights {
    Renderer& renderer;
    std::vector<Light> lights;
    ~RestoreLights() { renderer.set_lights(lights); }
  } restore{renderer_, scene_.lights};
  Scene scene = scene_;
  apply_light_choice("directional", scene);
  renderer_.set_lights(scene.lights);
  RenderSettings render = base_render_;
  render.view = View::TexelDensity;
  render.light_index = 0;

  LinePlot plot;
  plot.title = "The sun's texels per pixel against the distance from the camera";
  plot.x = {"distance from the camera (world units)", true};
  plot.y = {"texels per pixel (median of the pixels at that distance)", true};
  std::vector<std::vector<std::string>> data = {{"layout", "distance", "texels per pixel"}};
  std::vector<std::vector<std::string>> rows = {{"layout", "pixels seeing geometry",
                                                 "median texels per pixel", "at least 1 texel",
                                                 "pages resident of the pool (level bias)"}};
  std::vector<HtmlFigure> figures;
  double nearest = 0.0, farthest = 0.0;
  for (const MapLayout& layout : map_layouts(base_shadow_)) {
    figures.push_back(figure(renderer_, "directional",
                             "texel-density-" + std::to_string(figures.size()) + ".png",
                             layout.name + ": --view texel-density", render, layout.shadow));
    step();
    const bool drawn = !figures.back().image.empty();
    std::optional<Image> density;
    std::optional<SurfacePoints> surfaces;
    std::string pages = "-";
    if (drawn) {
      density = image_or_failure([&] { return renderer_.read_texel_density(); });
      if (!renderer_.virtual_lights().empty()) {
        const VirtualPageStats stats = renderer_.virtual_page_stats();
        pages = std::to_string(stats.resident) + " of " + std::to_string(stats.pool_pages) + " (" +
                fixed(0.5 * stats.bias, 1) + " levels finer)";
      }
      // The hard shadow of the same frame (its maps are not drawn again).
      if (const std::optional<Image> shadow = shaded(renderer_, View::Shadow)) {
        figures.push_back(
            written_figure(*shadow, "texel-density-" + std::to_string(figures.size()) + ".png",
                           layout.name + ": the hard shadow (--view shadow --technique hard)",
                           PngEncoding::Linear));
      }
      try {
        surfaces = renderer_.read_surfaces();
      } catch (const std::exception&) {
        ++failed_;
      }
    }
    if (!density || !surfaces) {
      rows.push_back({layout.name, "failed"});
      continue;
    }
    const TexelDensityShare share = texel_density_share(*density);
    rows.push_back({layout.name, std::to_string(share.pixels), fixed(share.median, 3),
                    fixed(100.0 * share.at_least_one, 1) + " %", pages});
    PlotSeries series{layout.name,
                      density_over_distance(*density, *surfaces, scene.camera.position), true};
    for (const PlotPoint& p : series.points) {
      data.push_back({layout.name, plot_number(p.x), plot_number(p.y)});
      nearest = nearest == 0.0 ? p.x : std::min(nearest, p.x);
      farthest = std::max(farthest, p.x);
    }
    plot.series.push_back(std::move(series));
  }
  if (farthest > nearest) {
    plot.series.push_back(
        {"one texel per pixel", {{nearest, 1.0, "", false}, {farthest, 1.0, "", false}}, true});
  }
  page.table(rows);
  page.plot(svg_line_plot(plot), data);
  page.figures(figures);
}

}  // namespace penumbra
