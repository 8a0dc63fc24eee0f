#include "report/study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

#include "app/command_line.hpp"
#include "app/light_choice.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/progress_bar.hpp"
#include "reference/error_image.hpp"
#include "reference/reference_cache.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/accumulation.hpp"
#include "render/pass_timing.hpp"
#include "render/renderer.hpp"
#include "report/foliage_scene.hpp"
#include "report/html_page.hpp"
#include "scene/gltf_scene.hpp"

namespace penumbra {

namespace {

std::string fixed(double value, int digits) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

std::string name_of(Technique t) {
  return std::string(enum_name<Technique>(kTechniqueNames, t));
}

class Study {
 public:
  Study(const Scene& scene, const StudyOptions& options, gl::Context& context)
      : scene_(scene), options_(options), context_(context), renderer_(scene) {
    base_render_.width = options.quick ? 320 : 640;
    base_render_.height = options.quick ? 180 : 360;
    base_shadow_.map_size = options.quick ? 1024 : 2048;
  }

  StudyResult run() {
    HtmlPage page("penumbra: shadow techniques on scene '" + scene_.name + "'");
    page.paragraph(
        "Every image below was rendered by penumbra on " + context_.renderer() + " (" +
        context_.version() +
        "). The command under each image re-makes it; run it in this folder. Shadow factors are "
        "1 where lit. Errors are measured against the filtered hard-shadow reference: the "
        "unfiltered shadow map's depth tests averaged with the technique's own filter kernel, "
        "each texel tested against the receiver's plane, which is what a filtered technique "
        "approximates.");
    techniques_section(page);
    light_types_section(page);
    maps_section(page);
    sweeps_section(page);
    esm_section(page);
    errors_section(page);
    foliage_section(page);
    timings_section(page);

    StudyResult result;
    result.index_path = (std::filesystem::path(options_.output_dir) / "index.html").string();
    write_file_atomically(result.index_path, page.finish());
    progress_.finish();
    result.items = items_;
    result.failed = failed_;
    return result;
  }

 private:
  // Renders one image into the report folder, or records why it failed.
  HtmlFigure figure(const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow) {
    return figure(renderer_, options_.light_choice, file, caption, render, shadow);
  }
  // The same with another renderer, made for the scene with `light_choice`.
  HtmlFigure figure(Renderer& renderer, const std::string& light_choice, const std::string& file,
                    const std::string& caption, RenderSettings render, ShadowSettings shadow) {
    return figure(renderer, options_.scene_argument, options_.model_argument, light_choice, file,
                  caption, render, shadow);
  }
  // The same for another scene, named by its --scene (or --model) argument.
  HtmlFigure figure(Renderer& renderer, const std::string& scene_argument,
                    const std::string& model_argument, const std::string& light_choice,
                    const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow) {
    HtmlFigure f;
    f.caption = caption;
    f.command = shell_command(render_command_args({.scene_argument = scene_argument,
                                                   .model_argument = model_argument,
                                                   .light = light_choice,
                                                   .render = render,
                                                   .shadow = shadow,
                                                   .ssao = {},
                                                   .original = nullptr,
                                                   .edited = nullptr,
                                                   .output = file}));
    ++items_;
    progress_.update(items_, total_items());
    try {
      renderer.render(render, shadow);
      const Image image = renderer.read_view();
      check_gl();
      write_png(image, (std::filesystem::path(options_.output_dir) / file).string(),
                png_encoding_for(render.view));
      f.image = file;
      f.width = image.width;
      f.height = image.height;
    } catch (const std::exception& e) {
      f.error = e.what();
      f.command.clear();
      ++failed_;
    }
    return f;
  }

  void check_gl() {
    if (context_.error_count() > errors_seen_) {
      errors_seen_ = context_.error_count();
      throw RuntimeError("OpenGL error: " + context_.last_error());
    }
  }

  ShadowSettings with(Technique t) const {
    ShadowSettings s = base_shadow_;
    s.technique = t;
    if (is_filterable(t)) s.blur = 4;
    return s;
  }

  void techniques_section(HtmlPage& page) {
    page.heading("1. The techniques side by side");
    page.paragraph(
        "The same scene, camera and lights for every technique: a spot light (front right) and a "
        "directional light (from the left). Filtered techniques use a Gaussian of radius W = 4 "
        "texels; the soft variants size their filter from a blocker search (PCSS, and the "
        "summed-area-table moment shadows).");
    std::vector<HtmlFigure> figures;
    for (Technique t : {Technique::None, Technique::Hard, Technique::Pcf, Technique::Pcss,
                        Technique::Backprojection, Technique::Vsm, Technique::Esm, Technique::Msm,
                        Technique::Msm16, Technique::Evsm2, Technique::Evsm4}) {
      figures.push_back(
          figure("technique-" + name_of(t) + ".png", name_of(t), base_render_, with(t)));
    }
    for (Technique t : {Technique::Vsm, Technique::Msm}) {
      ShadowSettings s = with(t);
      s.filter = Filter::Sat;
      s.soft = true;
      s.blur = 1;
      figures.push_back(figure("technique-" + name_of(t) + "-soft.png",
                               name_of(t) + " --soft (SAT)", base_render_, s));
    }
    RenderSettings ao = base_render_;
    ao.view = View::Ao;
    figures.push_back(figure("ambient-occlusion.png",
                             "the ambient-occlusion buffer (SSAO), which scales the ambient term",
                             ao, base_shadow_));
    page.figures(figures);
  }

  // The scene under one light of each type alone (what --light gives), so
  // the light types compare on equal terms: a spot light's one view, a
  // point light's six cube faces, the sun's cascades.
  void light_types_section(HtmlPage& page) {
    page.heading("2. Spot, point and directional lights");
    if (!options_.light_choice.empty()) {
      page.paragraph("This report was made with --light " + options_.light_choice +
                     ": without --light, this section compares the three light types.");
      return;
    }
    const int samples = options_.quick ? 64 : 256;
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
    const std::vector<Technique> techniques =
        options_.quick
            ? std::vector<Technique>{Technique::Hard, Technique::Pcss, Technique::Msm}
            : std::vector<Technique>{Technique::Hard,           Technique::Pcf, Technique::Pcss,
                                     Technique::Backprojection, Technique::Vsm, Technique::Msm};
    std::vector<std::vector<std::string>> rows = {{"technique"}};
    for (Technique t : techniques) rows.push_back({name_of(t)});
    std::vector<HtmlFigure> figures;
    for (LightType type : {LightType::Spot, LightType::Point, LightType::Directional}) {
      const std::string choice(enum_name<LightType>(kLightTypeNames, type));
      rows.front().push_back("RMSE " + choice);
      Scene scene = scene_;
      apply_light_choice(choice, scene);
      Renderer renderer(scene);
      for (Technique t : techniques) {
        figures.push_back(figure(renderer, choice, "light-" + choice + "-" + name_of(t) + ".png",
                                 choice + ", " + name_of(t), base_render_, with(t)));
      }
      std::vector<View> map_views = {View::ShadowMap};
      if (type == LightType::Directional) map_views.insert(map_views.begin(), View::Cascades);
      for (View view : map_views) {
        RenderSettings r = base_render_;
        r.view = view;
        const std::string name(enum_name<View>(kViewNames, view));
        figures.push_back(figure(renderer, choice, "light-" + choice + "-" + name + ".png",
                                 choice + ": --view " + name, r, base_shadow_));
      }
      measure_light_type(renderer, techniques, samples, rows);
    }
    page.table(rows);
    page.figures(figures);
  }

  // Appends each technique's RMSE against the light's traced reference to
  // its row (one row per technique, after the header).
  void measure_light_type(Renderer& renderer, const std::vector<Technique>& techniques, int samples,
                          std::vector<std::vector<std::string>>& rows) {
    ++items_;
    progress_.update(items_, total_items());
    std::optional<TracedReference> traced;
    try {
      traced = traced_reference(renderer, base_render_, base_shadow_, samples, default_cache_dir());
      check_gl();
    } catch (const std::exception&) {
      ++failed_;
    }
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      ++items_;
      progress_.update(items_, total_items());
      std::optional<Image> image =
          traced ? shadow_image(renderer, with(techniques[i])) : std::nullopt;
      rows[i + 1].push_back(image ? fixed(compare_shadow(*image, traced->image).rmse, 4)
                                  : "failed");
    }
  }

  void maps_section(HtmlPage& page) {
    page.heading("3. Shadow maps before and after the blur");
    page.paragraph(
        "The spot light's map as each technique stores it, as colour (moments z, z^2, z^3 in "
        "red, green, blue; msm16 shows its quantized channels), before and after a Gaussian of "
        "W = 8. ESM is shown as log(map)/c + 1, in depth units (EVSM likewise, from its positive "
        "warp exp(c+ (2z - 1))): after the blur that is "
        "log(blur(exp(c z)))/c + 1, which is not blur(z): the exponential weights the farthest "
        "depths most, so edges move towards the far side.");
    std::vector<HtmlFigure> figures;
    for (Technique t : {Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      ShadowSettings s = with(t);
      s.blur = 8;
      s.map_size = options_.quick ? 256 : 512;
      RenderSettings r = base_render_;
      r.view = View::Moments;
      figures.push_back(figure("map-" + name_of(t) + ".png", name_of(t) + ": map", r, s));
      r.view = View::MomentsFiltered;
      figures.push_back(
          figure("map-" + name_of(t) + "-blurred.png", name_of(t) + ": blurred, W = 8", r, s));
    }
    page.figures(figures);
  }

  void sweeps_section(HtmlPage& page) {
    page.heading("4. From anti-aliased to soft: filter widths and light sizes");
    page.paragraph(
        "W = 1 or 2 only anti-aliases the edge; W = 16 and 32 simulate a wide light. A fixed "
        "filter widens every penumbra alike, contact shadows included; PCSS widens them with "
        "the blocker-receiver distance (sharp at the box's foot, wide under the high slab).");
    const std::vector<int> widths =
        options_.quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32};
    const std::vector<Technique> swept =
        options_.quick ? std::vector<Technique>{Technique::Msm}
                       : std::vector<Technique>{Technique::Msm, Technique::Vsm, Technique::Esm,
                                                Technique::Msm16};
    for (Technique t : swept) {
      page.heading(name_of(t) + ", Gaussian of radius W", 3);
      std::vector<HtmlFigure> figures;
      for (int w : widths) {
        ShadowSettings s = with(t);
        s.blur = w;
        figures.push_back(figure("sweep-" + name_of(t) + "-w" + std::to_string(w) + ".png",
                                 name_of(t) + ", W = " + std::to_string(w), base_render_, s));
      }
      page.figures(figures);
    }
    page.heading("pcss, light sizes", 3);
    std::vector<HtmlFigure> figures;
    for (float size : {0.0f, 0.25f, 0.5f, 1.0f, 2.0f}) {
      ShadowSettings s = with(Technique::Pcss);
      s.light_size = size;
      figures.push_back(figure("sweep-pcss-light" + fixed(size, 2) + ".png",
                               "pcss, light size " + fixed(size, 2), base_render_, s));
    }
    page.figures(figures);
  }

  // The spot light's shadow factor against the filtered reference.
  std::optional<ShadowMetrics> measure_against_filtered(const ShadowSettings& shadow) {
    try {
      RenderSettings r = base_render_;
      r.view = View::Shadow;
      renderer_.render(r, shadow);
      const Image technique = renderer_.read_view();
      r.view = View::ShadowReference;
      renderer_.render(r, shadow);
      const Image reference = renderer_.read_view();
      check_gl();
      return compare_shadow(technique, reference);
    } catch (const std::exception&) {
      ++failed_;
      return std::nullopt;
    }
  }

  void esm_section(HtmlPage& page) {
    page.heading("5. The ESM exponent c");
    const std::vector<float> cs = {10.0f, 20.0f, 40.0f, 60.0f, 80.0f, kEsmMaxC};
    std::vector<HtmlFigure> figures;
    std::vector<std::vector<std::string>> rows = {
        {"c", "mean abs. error", "light leaking", "over-darkening", "max error"}};
    struct Point {
      float c;
      ShadowMetrics m;
    };
    std::vector<Point> points;
    for (float c : cs) {
      ShadowSettings s = with(Technique::Esm);
      s.esm_c = c;
      figures.push_back(
          figure("esm-c" + fixed(c, 0) + ".png", "esm, c = " + fixed(c, 0), base_render_, s));
      ++items_;
      progress_.update(items_, total_items());
      if (auto m = measure_against_filtered(s)) {
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
        "the reverse (reference > 0.9, technique < 0.7).");
    page.table(rows);
    if (!points.empty()) page.paragraph(esm_discussion(points.front().c, points.back().c, points));
    page.figures(figures);
  }

  template <class Points>
  static std::string esm_discussion(float lowest, float highest, const Points& points) {
    const auto best =
        std::min_element(points.begin(), points.end(), [](const auto& a, const auto& b) {
          return a.m.mean_absolute_error < b.m.mean_absolute_error;
        });
    const auto& first = points.front().m;
    const auto& last = points.back().m;
    std::ostringstream out;
    out << "What c trades: the test exp(-c (z_f - z)) darkens a receiver only once it is "
           "several 1/c behind its occluder, so a small c leaves a lit band where shadows "
           "begin (light leaking near contact) and fades them; a large c makes the test sharp "
           "but also sharpens the filtered edge away from the reference. Here the mean error "
           "goes from "
        << fixed(first.mean_absolute_error, 4) << " at c = " << fixed(lowest, 0) << " to "
        << fixed(last.mean_absolute_error, 4) << " at c = " << fixed(highest, 0)
        << ", and light leaking from " << fixed(100.0 * first.leak_fraction, 3) << " % to "
        << fixed(100.0 * last.leak_fraction, 3)
        << " % of the pixels. On this scene c = " << fixed(best->c, 0)
        << " wins, with a mean error of " << fixed(best->m.mean_absolute_error, 4) << ".";
    return out.str();
  }

  // The spot light's shadow factor of a technique, or nullopt on failure.
  std::optional<Image> shadow_image(const ShadowSettings& shadow, View view = View::Shadow) {
    return shadow_image(renderer_, shadow, view);
  }
  std::optional<Image> shadow_image(Renderer& renderer, const ShadowSettings& shadow,
                                    View view = View::Shadow) {
    return shadow_image(renderer, base_render_, shadow, view);
  }
  std::optional<Image> shadow_image(Renderer& renderer, const RenderSettings& render,
                                    const ShadowSettings& shadow, View view = View::Shadow) {
    try {
      RenderSettings r = render;
      r.view = view;
      renderer.render(r, shadow);
      Image image = renderer.read_view();
      check_gl();
      return image;
    } catch (const std::exception&) {
      ++failed_;
      return std::nullopt;
    }
  }

  void errors_section(HtmlPage& page) {
    page.heading("6. Errors against the references");
    const int samples = options_.quick ? 64 : 256;
    std::optional<TracedReference> traced;
    ++items_;
    progress_.update(items_, total_items());
    try {
      traced =
          traced_reference(renderer_, base_render_, base_shadow_, samples, default_cache_dir());
      check_gl();
    } catch (const std::exception& e) {
      ++failed_;
      page.paragraph(std::string("The traced reference failed: ") + e.what());
    }
    page.paragraph(
        "The spot light's shadow factor over the pixels that see geometry inside its cone, "
        "against two references. Traced: the ground truth, shadow rays from every pixel's "
        "surface point to the light's square source (" +
        fixed(base_shadow_.light_size, 2) + " wide, " + std::to_string(samples) +
        " stratified rays per pixel), traced with Embree through the same triangles; `penumbra "
        "compare` computes the same. Filtered: the unfiltered map's depth tests averaged with the "
        "technique's own kernel (Gaussian, W = 4), what a filtered technique approximates. Light "
        "leaking counts pixels the reference has in shadow (< 0.1) that the technique lights "
        "(> 0.3); over-darkening the reverse (reference > 0.9, technique < 0.7). The error "
        "images show technique minus traced reference: red where the technique is too light, "
        "blue where too dark. The last row is not a single frame: hard shadows from N points "
        "spread over the source, weighted as the reference weighs them and averaged "
        "(`--accumulate N`), the converged result the single-frame techniques approximate.");
    std::vector<std::vector<std::string>> rows = {{"technique", "MAE traced", "RMSE traced",
                                                   "leaking traced", "over-dark traced",
                                                   "MAE filtered", "leaking filtered"}};
    std::vector<HtmlFigure> figures;
    // One row and one error image: `label` names the setting, `stem` its files.
    const auto add_row = [&](const std::string& label, const std::string& stem,
                             const ShadowSettings& settings, const std::optional<Image>& image) {
      if (!image || !traced) {
        rows.push_back({label, "failed"});
        return;
      }
      const ShadowMetrics m = compare_shadow(*image, traced->image);
      std::vector<std::string> row = {label, fixed(m.mean_absolute_error, 4), fixed(m.rmse, 4),
                                      fixed(100.0 * m.leak_fraction, 3) + " %",
                                      fixed(100.0 * m.over_dark_fraction, 3) + " %"};
      std::optional<Image> reference;
      if (is_filterable(settings.technique)) {
        reference = shadow_image(settings, View::ShadowReference);
      }
      if (reference) {
        const ShadowMetrics f = compare_shadow(*image, *reference);
        row.push_back(fixed(f.mean_absolute_error, 4));
        row.push_back(fixed(100.0 * f.leak_fraction, 3) + " %");
      } else {
        row.push_back("");
        row.push_back("");
      }
      rows.push_back(row);
      HtmlFigure f;
      f.caption = label + " minus traced";
      f.image = "error-" + stem + ".png";
      try {
        const Image error = error_image(*image, traced->image);
        write_png(error, (std::filesystem::path(options_.output_dir) / f.image).string(),
                  PngEncoding::Linear);
        f.width = error.width;
        f.height = error.height;
      } catch (const std::exception& e) {
        f.error = e.what();
        ++failed_;
      }
      figures.push_back(f);
    };
    for (Technique t : {Technique::Hard, Technique::Pcf, Technique::Pcss, Technique::Backprojection,
                        Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      ++items_;
      progress_.update(items_, total_items());
      const ShadowSettings settings = with(t);
      add_row(name_of(t), name_of(t), settings, shadow_image(settings));
    }
    // The converged counterpart: hard shadows from N points of the source,
    // weighted as the reference weighs them (render/accumulation.hpp).
    ++items_;
    progress_.update(items_, total_items());
    ShadowSettings accumulated = with(Technique::Hard);
    accumulated.accumulate = options_.quick ? 8 : 64;
    const std::string label = "hard --accumulate " + std::to_string(accumulated.accumulate);
    try {
      RenderSettings r = base_render_;
      r.view = View::Shadow;
      const Image image = render_accumulated(renderer_, r, accumulated);
      check_gl();
      add_row(label, "hard-accumulate", accumulated, image);
    } catch (const std::exception&) {
      ++failed_;
      add_row(label, "hard-accumulate", accumulated, std::nullopt);
    }
    page.table(rows);
    page.figures(figures);
  }

  // Alpha-tested casters: the foliage scene (report/foliage_scene.hpp),
  // each technique against the traced reference of each of its lights.
  void foliage_section(HtmlPage& page) {
    page.heading("7. Foliage: alpha-tested casters");
    const int samples = options_.quick ? 64 : 256;
    const std::vector<Technique> techniques =
        options_.quick
            ? std::vector<Technique>{Technique::Hard, Technique::Pcf, Technique::Pcss,
                                     Technique::Vsm, Technique::Msm}
            : std::vector<Technique>{
                  Technique::Hard,  Technique::Pcf,  Technique::Pcss, Technique::Backprojection,
                  Technique::Vsm,   Technique::Esm,  Technique::Msm,  Technique::Msm16,
                  Technique::Evsm2, Technique::Evsm4};
    // The scene's files go into the report's folder, so the commands under
    // the images run there as they are.
    const std::string scene_argument = "foliage/foliage.gltf";
    std::optional<Scene> scene;
    try {
      write_foliage_scene((std::filesystem::path(options_.output_dir) / "foliage").string());
      scene = gltf_scene((std::filesystem::path(options_.output_dir) / scene_argument).string());
    } catch (const std::exception& e) {
      ++failed_;
      page.paragraph(std::string("The foliage scene could not be read: ") + e.what());
      return;
    }
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
    for (std::size_t light = 0; light < scene->lights.size(); ++light) {
      const std::string light_name =
          std::string(enum_name<LightType>(kLightTypeNames, scene->lights[light].type));
      rows.front().push_back("RMSE " + light_name);
      rows.front().push_back("leaking " + light_name);
      RenderSettings render = base_render_;
      render.light_index = static_cast<int>(light);
      ++items_;
      progress_.update(items_, total_items());
      std::optional<TracedReference> traced;
      try {
        traced = traced_reference(renderer, render, base_shadow_, samples, default_cache_dir());
        check_gl();
        const std::string file = "foliage-" + light_name + "-traced.png";
        write_png(traced->image, (std::filesystem::path(options_.output_dir) / file).string(),
                  PngEncoding::Linear);
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
        ++items_;
        progress_.update(items_, total_items());
        std::optional<Image> image;
        if (traced) image = shadow_image(renderer, render, with(techniques[i]));
        if (!image) {
          rows[i + 1].insert(rows[i + 1].end(), {"failed", ""});
          continue;
        }
        const ShadowMetrics m = compare_shadow(*image, traced->image);
        measured.push_back({techniques[i], m});
        rows[i + 1].push_back(fixed(m.rmse, 4));
        rows[i + 1].push_back(fixed(100.0 * m.leak_fraction, 2) + " %");
        const std::string file =
            "foliage-" + light_name + "-error-" + name_of(techniques[i]) + ".png";
        const Image error = error_image(*image, traced->image);
        write_png(error, (std::filesystem::path(options_.output_dir) / file).string(),
                  PngEncoding::Linear);
        figures.push_back(image_figure(file,
                                       light_name + ", " + name_of(techniques[i]) + " minus traced",
                                       error.width, error.height));
      }
      if (!measured.empty()) summary.push_back(foliage_summary(light_name, measured));
    }
    page.table(rows);
    for (const std::string& sentence : summary) page.paragraph(sentence);
    page.figures(figures);
  }

  // What the numbers of one light say: the technique closest to the
  // traced reference, those much further off, and the filtered ones that
  // leak light through the cut-outs more often than the hard map.
  static std::string foliage_summary(
      const std::string& light, const std::vector<std::pair<Technique, ShadowMetrics>>& measured) {
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

  void timings_section(HtmlPage& page) {
    page.heading("8. GPU time per pass");
    const bool timer = !timers_miss_compute(context_.renderer());
    page.paragraph(
        "Device: " + context_.renderer() + " (" + context_.vendor() + ", " + context_.version() +
        "). Median of " + std::to_string(kTimedFrames) + " frames at " +
        std::to_string(base_render_.width) + "x" + std::to_string(base_render_.height) +
        " with a " + std::to_string(base_shadow_.map_size) + "^2 map, passes serialized, in ms (" +
        (timer ? "GPU timer queries"
               : "wall clock: this renderer's timer queries miss compute work") +
        "). The last columns put each filter pass against a compute copy of the same map (one "
        "read, one write per texel): the filters are memory-bound, so that ratio says how close "
        "they come to the bandwidth limit. `penumbra bench` measures more.");
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> header = {"technique"};
    for (std::size_t p = 0; p < kPassCount; ++p) header.emplace_back(gl::kGpuPassNames[p]);
    header.emplace_back("total");
    header.emplace_back("filters / copy");
    rows.push_back(header);
    for (Technique t : {Technique::Hard, Technique::Pcf, Technique::Pcss, Technique::Backprojection,
                        Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      ++items_;
      progress_.update(items_, total_items());
      try {
        const PassTimes times =
            measure_pass_times(renderer_, base_render_, with(t), kTimedFrames, 1);
        check_gl();
        std::vector<std::string> row = {name_of(t)};
        for (std::size_t p = 0; p < kPassCount; ++p) {
          const Samples& s = times.passes[p];
          row.push_back(times.ran[p] ? fixed(spread_of(timer ? s.timer_ms : s.wall_ms).median, 2)
                                     : "");
        }
        row.push_back(
            fixed(spread_of(timer ? times.total.timer_ms : times.total.wall_ms).median, 2));
        std::string ratios;
        for (const auto& [name, ratio] : copy_ratios(times, timer).values) {
          ratios += (ratios.empty() ? "" : ", ") + name + " " + fixed(ratio, 1) + "x";
        }
        row.push_back(ratios);
        rows.push_back(row);
      } catch (const std::exception& e) {
        ++failed_;
        rows.push_back({name_of(t), std::string("failed: ") + e.what()});
      }
    }
    page.table(rows);
  }

  static constexpr int kTimedFrames = 3;

  const Scene& scene_;
  StudyOptions options_;
  gl::Context& context_;
  Renderer renderer_;
  RenderSettings base_render_;
  ShadowSettings base_shadow_;
  // Images, metrics and timings the study makes, for the progress bar.
  // The foliage section: its scene image, and per light (2) a trace and
  // each technique (5 or 10).
  int total_items() const { return options_.quick ? 94 + 13 : 133 + 23; }
  ProgressBar progress_{"report"};
  int items_ = 0;
  int failed_ = 0;
  int errors_seen_ = 0;
};

}  // namespace

StudyResult write_study(const Scene& scene, const StudyOptions& options, gl::Context& context) {
  std::filesystem::create_directories(options.output_dir);
  return Study(scene, options, context).run();
}

}  // namespace penumbra
