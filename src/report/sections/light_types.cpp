#include "report/study_run.hpp"

#include <vector>

#include "app/light_choice.hpp"

namespace penumbra {

namespace {

constexpr LightType kLightTypes[] = {LightType::Spot, LightType::Point, LightType::Directional};

std::vector<Technique> light_type_techniques(bool quick) {
  return quick ? std::vector<Technique>{Technique::Hard, Technique::Pcss, Technique::Msm}
               : std::vector<Technique>{Technique::Hard,           Technique::Pcf, Technique::Pcss,
                                        Technique::Backprojection, Technique::Vsm, Technique::Msm};
}

// The map views shown for a light type: its shadow map, and a sun's
// cascades.
std::vector<View> map_views(LightType type) {
  std::vector<View> views = {View::ShadowMap};
  if (type == LightType::Directional) views.insert(views.begin(), View::Cascades);
  return views;
}

}  // namespace

// Per light type: a figure per technique and map view, its traced
// reference and a measurement per technique.
int Study::light_types_items() const {
  if (!options_.light_choice.empty()) return 0;
  const auto techniques = static_cast<int>(light_type_techniques(options_.quick).size());
  int items = 0;
  for (LightType type : kLightTypes) {
    items += techniques + static_cast<int>(map_views(type).size()) + 1 + techniques;
  }
  return items;
}

// The scene under one light of each type alone (what --light gives), so
// the light types compare on equal terms: a spot light's one view, a
// point light's six cube faces, the sun's cascades.
void Study::light_types_section(HtmlPage& page) {
  section(page, "lights", "2. Spot, point and directional lights");
  if (!options_.light_choice.empty()) {
    page.paragraph("This report was made with --light " + options_.light_choice +
                   ": without --light, this section compares the three light types.");
    return;
  }
  const int samples = traced_samples();
  page.paragraph(
      "The scene lit by one light of each type alone (--light), each as bright at the scene's "
      "centre as its key light. A point light's shadow is read from the six faces of a cube, "
      "each widened by a guard band so that filters near a face's edge read their own face; "
      "the directional light's from " +
      std::to_string(base_shadow_.cascades) +
      " cascades fitted to the camera (--view cascades shows which pixel reads which). The "
      "table gives each technique's shadow factor against the traced reference of that light "
      "(" +
      std::to_string(samples) +
      " rays per pixel; the point light a sphere of the light size, the sun a disk of its "
      "angle), over the pixels the light reaches.");
  const std::vector<Technique> techniques = light_type_techniques(options_.quick);
  std::vector<std::vector<std::string>> rows = {{"technique"}};
  for (Technique t : techniques) rows.push_back({name_of(t)});
  std::vector<HtmlFigure> figures;
  // The study's renderer with each light in turn (the geometry and the
  // camera are the same, so its shaders, G-buffer and ambient occlusion
  // serve every light), given its own lights back at the end.
  struct RestoreLights {
    Renderer& renderer;
    std::vector<Light> lights;
    ~RestoreLights() { renderer.set_lights(lights); }
  } restore{renderer_, scene_.lights};
  Renderer& renderer = renderer_;
  for (LightType type : kLightTypes) {
    const std::string choice(enum_name<LightType>(kLightTypeNames, type));
    rows.front().push_back("RMSE " + choice);
    Scene scene = scene_;
    apply_light_choice(choice, scene);
    renderer.set_lights(scene.lights);
    std::vector<std::optional<Image>> shadows(techniques.size());
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      const Technique t = techniques[i];
      // Each technique makes its own filtered arrays (a point light's six
      // faces of them), as in section 1.
      renderer.release_filtered_maps();
      figures.push_back(figure(renderer, choice, "light-" + choice + "-" + name_of(t) + ".png",
                               choice + ", " + name_of(t), base_render_, with(t), &shadows[i]));
    }
    // The map views read the depth maps alone: the techniques' filtered
    // arrays (a point light's six faces of them) go before the tiled
    // image of the maps is made and read.
    renderer.release_filtered_maps();
    for (View view : map_views(type)) {
      RenderSettings r = base_render_;
      r.view = view;
      const std::string name(enum_name<View>(kViewNames, view));
      figures.push_back(figure(renderer, choice, "light-" + choice + "-" + name + ".png",
                               choice + ": --view " + name, r, base_shadow_));
    }
    const std::vector<double> rmse = measure_light_type(shadows, rows);
    if (type == LightType::Directional) {
      for (std::size_t i = 0; i < techniques.size(); ++i) {
        if (rmse[i] >= 0.0) findings_.directional_rmse.push_back({name_of(techniques[i]), rmse[i]});
      }
    }
  }
  page.table(rows);
  page.figures(figures);
}

// Appends each technique's RMSE against the light's traced reference to
// its row (one row per technique's shadow factor, after the header);
// returns them (-1 where one failed).
std::vector<double> Study::measure_light_type(const std::vector<std::optional<Image>>& shadows,
                                              std::vector<std::vector<std::string>>& rows) {
  step();
  std::optional<TracedReference> traced;
  try {
    traced = trace(renderer_, base_render_, base_shadow_);
    check_gl();
  } catch (const std::exception&) {
    ++failed_;
  }
  std::vector<double> rmse;
  for (std::size_t i = 0; i < shadows.size(); ++i) {
    step();
    const bool measured = traced && shadows[i];
    rmse.push_back(measured ? compare_shadow(*shadows[i], traced->image).rmse : -1.0);
    rows[i + 1].push_back(measured ? fixed(rmse.back(), 4) : "failed");
  }
  return rmse;
}

}  // namespace penumbra
