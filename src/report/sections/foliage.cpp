#include "report/study_run.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "reference/error_image.hpp"
#include "report/foliage_scene.hpp"
#include "report/svg_plot.hpp"
#include "scene/gltf_scene.hpp"

namespace penumbra {

namespace {

std::vector<Technique> foliage_techniques(bool quick) {
  return quick ? std::vector<Technique>{Technique::Hard, Technique::Pcf, Technique::Pcss,
                                        Technique::Vsm, Technique::Msm}
               : std::vector<Technique>{
                     Technique::Hard,  Technique::Pcf,  Technique::Pcss, Technique::Backprojection,
                     Technique::Vsm,   Technique::Esm,  Technique::Msm,  Technique::Msm16,
                     Technique::Evsm2, Technique::Evsm4};
}

// The map sizes the foliage section measures, and with which techniques.
std::vector<int> foliage_map_sizes_measured() {
  return {512, 1024, 2048};
}
std::vector<Technique> foliage_swept_techniques(bool quick) {
  return quick ? std::vector<Technique>{Technique::Hard}
               : std::vector<Technique>{Technique::Hard, Technique::Pcf, Technique::Pcss,
                                        Technique::Vsm, Technique::Msm};
}

// The lights of the foliage scene's glTF file (KHR_lights_punctual), for
// the progress total before the section reads the scene.
int foliage_light_count() {
  for (const EmbeddedFile& file : foliage_scene_files()) {
    if (file.name != "foliage.gltf") continue;
    const nlohmann::json gltf = nlohmann::json::parse(file.bytes, nullptr, false);
    const auto lights = gltf.is_discarded()
                            ? nlohmann::json()
                            : gltf.value("extensions", nlohmann::json::object())
                                  .value("KHR_lights_punctual", nlohmann::json::object())
                                  .value("lights", nlohmann::json::array());
    return lights.is_array() ? static_cast<int>(lights.size()) : 0;
  }
  return 0;
}

// Sum of (1 - technique) over sum of (1 - reference), over the pixels both
// judge (alpha >= 0.5); 1 when the reference has no shadow there.
double total_shadow_ratio(const Image& technique, const Image& reference) {
  double t = 0.0, r = 0.0;
  for (std::size_t i = 0; i + 3 < technique.rgba.size() && i + 3 < reference.rgba.size(); i += 4) {
    if (technique.rgba[i + 3] < 0.5f || reference.rgba[i + 3] < 0.5f) continue;
    t += 1.0 - double(technique.rgba[i]);
    r += 1.0 - double(reference.rgba[i]);
  }
  return r > 0.0 ? t / r : 1.0;
}

// What the numbers of one light say: the technique closest to the
// traced reference, those much further off, and the filtered ones that
// leak light through the cut-outs more often than the hard map.
std::string foliage_summary(const std::string& light,
                            const std::vector<std::pair<Technique, ShadowMetrics>>& measured) {
  const auto best = std::min_element(measured.begin(), measured.end(), [](auto& a, auto& b) {
    return a.second.rmse < b.second.rmse;
  });
  const auto hard = std::find_if(measured.begin(), measured.end(),
                                 [](auto& m) { return m.first == Technique::Hard; });
  std::ostringstream out;
  out << "Under the " << light << " light, " << name_of(best->first)
      << " is closest to the traced reference (RMSE " << fixed(best->second.rmse, 4) << ").";
  std::vector<std::string> far_off, leaky;
  for (const auto& [t, m] : measured) {
    if (m.rmse > 1.5 * best->second.rmse) {
      far_off.push_back(name_of(t) + " " + fixed(m.rmse, 4));
    }
    if (is_filterable(t) && hard != measured.end() &&
        m.leak_fraction > 2.0 * hard->second.leak_fraction && m.leak_fraction > 1e-3) {
      leaky.push_back(name_of(t) + " " + fixed(100.0 * m.leak_fraction, 2) + " %");
    }
  }
  const auto join = [](const std::vector<std::string>& items) {
    std::string text;
    for (std::size_t i = 0; i < items.size(); ++i) {
      text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
    }
    return text;
  };
  if (!far_off.empty()) {
    out << " More than 1.5 times its error: " << join(far_off) << ".";
  } else {
    out << " Every technique is within 1.5 times its error.";
  }
  if (hard == measured.end()) return out.str();
  if (!leaky.empty()) {
    out << " Struggling with the cut-outs, the filtered representations leak light through "
           "leaves and slats on more than twice the hard map's share of pixels ("
        << fixed(100.0 * hard->second.leak_fraction, 2) << " %): " << join(leaky) << ".";
  } else {
    out << " No filtered technique leaks on more than twice the hard map's share of pixels ("
        << fixed(100.0 * hard->second.leak_fraction, 2) << " %).";
  }
  return out.str();
}

}  // namespace

// The scene's figure; per light its traced reference and a measurement
// per technique, then the other map sizes' measurements.
int Study::foliage_items() const {
  const int lights = foliage_light_count();
  const auto techniques = static_cast<int>(foliage_techniques(options_.quick).size());
  const std::vector<int> sizes = foliage_map_sizes_measured();
  const auto other_sizes =
      static_cast<int>(sizes.size() - static_cast<std::size_t>(std::count(
                                          sizes.begin(), sizes.end(), base_shadow_.map_size)));
  const auto swept = static_cast<int>(foliage_swept_techniques(options_.quick).size());
  return 1 + lights * (1 + techniques) + lights * swept * other_sizes;
}

// Alpha-tested casters: the foliage scene (report/foliage_scene.hpp),
// each technique against the traced reference of each of its lights.
void Study::foliage_section(HtmlPage& page) {
  section(page, "foliage", "8. Foliage: alpha-tested casters");
  const int samples = traced_samples();
  const std::vector<Technique> techniques = foliage_techniques(options_.quick);
  const std::string scene_argument = "foliage/foliage.gltf";
  // The scene's files go into the report's folder, so the commands under
  // the images run there as they are. Written here, not before: an
  // interrupted report removes its staged folder's files, and the study
  // writes no folder inside it before it must.
  try {
    write_foliage_scene((std::filesystem::path(options_.output_dir) / "foliage").string());
    foliage_scene_ =
        gltf_scene((std::filesystem::path(options_.output_dir) / scene_argument).string());
  } catch (const std::exception& e) {
    ++failed_;
    page.paragraph(std::string("The foliage scene could not be read: ") + e.what());
    return;
  }
  const Scene* scene = &*foliage_scene_;
  page.paragraph(
      "The scene scripts/make-foliage-scene writes (built into penumbra, written next to this "
      "page as " +
      scene_argument +
      "): a ground, three trees whose crowns are alpha-masked "
      "leaf cards, a fence of 8 cm slats and a grille cut out by a mask, under a sun (" +
      std::to_string(base_shadow_.cascades) +
      " cascades) and a warm spot light, seen by the file's camera. Many depth "
      "discontinuities per texel: the hardest case for filtered maps. Each technique's shadow "
      "factor for each light alone (--light-index) against that light's traced reference (" +
      std::to_string(samples) +
      " rays per pixel through the same cut-outs), over the pixels the light reaches; leaking "
      "and the error images as in section 6.");
  Renderer renderer(*scene);
  const auto image_figure = [](const std::string& file, const std::string& caption, int width,
                               int height) {
    HtmlFigure f;
    f.image = file;
    f.caption = caption;
    f.width = width;
    f.height = height;
    return f;
  };
  std::vector<HtmlFigure> figures;
  figures.push_back(figure(renderer, scene_argument, "", "", "foliage.png",
                           "the foliage scene, pcss", base_render_, with(Technique::Pcss)));
  std::vector<std::vector<std::string>> rows = {{"technique"}};
  for (Technique t : techniques) rows.push_back({name_of(t)});
  std::vector<std::string> summary;
  std::vector<std::optional<TracedReference>> traced_by_light(scene->lights.size());
  // Per light, each technique's image at the base map size, measured.
  std::vector<std::vector<std::optional<FoliageMeasure>>> base_measures(
      scene->lights.size(), std::vector<std::optional<FoliageMeasure>>(techniques.size()));
  for (std::size_t light = 0; light < scene->lights.size(); ++light) {
    const std::string light_name =
        std::string(enum_name<LightType>(kLightTypeNames, scene->lights[light].type));
    rows.front().push_back("RMSE " + light_name);
    rows.front().push_back("leaking " + light_name);
    RenderSettings render = base_render_;
    render.light_index = static_cast<int>(light);
    step();
    std::optional<TracedReference>& traced = traced_by_light[light];
    try {
      traced = trace(renderer, render, base_shadow_);
      check_gl();
      const std::string file = "foliage-" + light_name + "-traced.png";
      write_report_png(traced->image, file, PngEncoding::Linear);
      figures.push_back(image_figure(file, light_name + ": traced reference", traced->image.width,
                                     traced->image.height));
    } catch (const std::exception& e) {
      ++failed_;
      HtmlFigure failed;
      failed.caption = light_name + ": traced reference";
      failed.error = e.what();
      figures.push_back(failed);
    }
    std::vector<std::pair<Technique, ShadowMetrics>> measured;
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      step();
      std::optional<Image> image;
      if (traced) image = shadow_image(renderer, render, with(techniques[i]));
      if (!image) {
        rows[i + 1].insert(rows[i + 1].end(), {"failed", ""});
        continue;
      }
      const ShadowMetrics m = compare_shadow(*image, traced->image);
      measured.push_back({techniques[i], m});
      base_measures[light][i] = FoliageMeasure{m.rmse, total_shadow_ratio(*image, traced->image)};
      rows[i + 1].push_back(fixed(m.rmse, 4));
      rows[i + 1].push_back(fixed(100.0 * m.leak_fraction, 2) + " %");
      const std::string file =
          "foliage-" + light_name + "-error-" + name_of(techniques[i]) + ".png";
      const Image error = error_image(*image, traced->image);
      write_report_png(error, file, PngEncoding::Linear);
      figures.push_back(image_figure(file,
                                     light_name + ", " + name_of(techniques[i]) + " minus traced",
                                     error.width, error.height));
    }
    if (!measured.empty()) {
      summary.push_back(foliage_summary(light_name, measured));
      // The verdict's foliage line: the first light's closest technique.
      if (!findings_.foliage) {
        const auto best = std::min_element(measured.begin(), measured.end(), [](auto& a, auto& b) {
          return a.second.rmse < b.second.rmse;
        });
        findings_.foliage =
            VerdictLine{"Foliage and other alpha-tested casters",
                        name_of(best->first),
                        "RMSE ",
                        fixed(best->second.rmse, 4),
                        " under the " + light_name + " light, the closest to the traced reference.",
                        "foliage",
                        "section 8"};
      }
    }
  }
  page.table(rows);
  for (const std::string& sentence : summary) page.paragraph(sentence);
  foliage_map_sizes(page, renderer, techniques, traced_by_light, base_measures);
  page.graphic(svg_error_color_bar(kErrorImageRange, "technique - traced reference"));
  page.figures(figures);
}

// The same measurements at each map size of kFoliageMapSizes: an
// alpha-tested caster's coverage, as the shadow pass rasterizes it, must
// not thin out in a coarser map (issue: leaves keep their coverage at every
// map size). The total shadow is the sum of (1 - shadow factor) over the
// pixels both judge, the technique's over the traced reference's: below 1
// where the cut-outs let through light the reference does not.
void Study::foliage_map_sizes(
    HtmlPage& page, Renderer& renderer, const std::vector<Technique>& techniques,
    const std::vector<std::optional<TracedReference>>& traced,
    const std::vector<std::vector<std::optional<FoliageMeasure>>>& base_measures) {
  const std::vector<Technique> swept = foliage_swept_techniques(options_.quick);
  const std::vector<int> sizes = foliage_map_sizes_measured();
  std::vector<std::string> header = {"light", "technique"};
  for (int size : sizes) header.push_back("RMSE " + map_size_text(size));
  for (int size : sizes) header.push_back("total shadow " + map_size_text(size));
  std::vector<std::vector<std::string>> rows = {header};
  for (std::size_t light = 0; light < traced.size(); ++light) {
    const std::string light_name =
        std::string(enum_name<LightType>(kLightTypeNames, foliage_scene_->lights[light].type));
    RenderSettings render = base_render_;
    render.light_index = static_cast<int>(light);
    for (Technique t : swept) {
      std::vector<std::string> rmse, shadow;
      for (int size : sizes) {
        std::optional<FoliageMeasure> m;
        if (size == base_shadow_.map_size) {
          // Measured for the table above.
          const auto i = static_cast<std::size_t>(
              std::find(techniques.begin(), techniques.end(), t) - techniques.begin());
          if (i < techniques.size()) m = base_measures[light][i];
        } else {
          step();
          ShadowSettings s = with(t);
          s.map_size = size;
          std::optional<Image> image;
          if (traced[light]) image = shadow_image(renderer, render, s);
          if (image) {
            m = FoliageMeasure{compare_shadow(*image, traced[light]->image).rmse,
                               total_shadow_ratio(*image, traced[light]->image)};
          }
        }
        rmse.push_back(m ? fixed(m->rmse, 4) : "failed");
        shadow.push_back(m ? fixed(m->total_shadow, 3) : "");
      }
      std::vector<std::string> row = {light_name, name_of(t)};
      row.insert(row.end(), rmse.begin(), rmse.end());
      row.insert(row.end(), shadow.begin(), shadow.end());
      rows.push_back(row);
    }
  }
  page.heading("Map sizes", 3);
  page.paragraph(
      "The cut-outs at each shadow-map size: RMSE against the same traced reference, and the "
      "total shadow, the sum of (1 - shadow factor) over the pixels both judge, the "
      "technique's over the reference's (1: as much shadow as the reference; below 1: leaves "
      "and slats that a coarser map loses let light through).");
  page.table(rows);
}

}  // namespace penumbra
