#include "report/study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <list>
#include <sstream>

#include "app/command_line.hpp"
#include "app/light_choice.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/progress_bar.hpp"
#include "penumbra/error.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "reference/error_image.hpp"
#include "reference/reference_cache.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/accumulation.hpp"
#include "render/pass_timing.hpp"
#include "render/renderer.hpp"
#include "report/crop_regions.hpp"
#include "report/edge_errors.hpp"
#include "report/foliage_scene.hpp"
#include "report/html_page.hpp"
#include "report/ranking.hpp"
#include "report/svg_plot.hpp"
#include "report/verdict.hpp"
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

// Bytes per texel of the map a technique's lookup reads: the depth map for
// the techniques that test depths, the representation for the others.
int map_bytes_per_texel(Technique t) {
  return bytes_per_texel(is_filterable(t) ? representation_format(t) : ShadowMapPass::kDepthFormat);
}

// One technique's (or setting's) errors against the traced reference.
struct MeasuredError {
  std::string label;  // as the tables name it
  std::string stem;   // its files: shadow-STEM.png, error-STEM.png
  Technique technique = Technique::Hard;
  bool single_frame = true;  // false for --accumulate
  ShadowMetrics traced;
  Image image;  // the spot light's shadow factor
};

constexpr const char* kRmseLabel = "RMSE against the traced reference (shadow factor)";

// The sizes a study renders and traces at: the full study's, or --quick's.
struct StudySize {
  int width, height;  // of every frame
  int map_size;       // of every shadow map but section 3's
  int samples;        // rays per pixel of the traced references
};
constexpr StudySize kFullSize{640, 360, 2048, 256};
// --quick: a 512^2 map still has a texel per pixel or more across the
// spot light's cone at 320x180, for a quarter of the filters' work.
constexpr StudySize kQuickSize{320, 180, 512, 64};

std::string map_size_text(int size) {
  return std::to_string(size) + "^2";
}

class Study {
 public:
  Study(const Scene& scene, const StudyOptions& options, gl::Context& context)
      : scene_(scene), options_(options), context_(context), renderer_(scene) {
    const StudySize& size = options.quick ? kQuickSize : kFullSize;
    base_render_.width = size.width;
    base_render_.height = size.height;
    base_shadow_.map_size = size.map_size;
  }

  StudyResult run() {
    HtmlPage page("penumbra: shadow techniques on scene '" + scene_.name + "'");
    page.paragraph(
        "Every image below was rendered by penumbra on " + context_.renderer() + " (" +
        context_.version() +
        "). The command under each image re-makes it; run it in this folder; click an image for "
        "its full size. Shadow factors are 1 where lit. Errors are measured against the "
        "filtered hard-shadow reference: the unfiltered shadow map's depth tests averaged with "
        "the technique's own filter kernel, each texel tested against the receiver's plane, "
        "which is what a filtered technique approximates, and against a ray-traced reference.");
    if (options_.quick) page.banner(quick_banner());
    techniques_section(page);
    light_types_section(page);
    maps_section(page);
    sweeps_section(page);
    esm_section(page);
    errors_section(page);
    closeups_section(page);
    foliage_section(page);
    timings_section(page);
    progress_.step("the verdict and the page", items_, total_items());
    verdict(page);

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
  // With `shadow_factor`, also the spot light's shadow factor of the same
  // frame (Renderer::shade: its maps are not rendered again), for the
  // measurements of the same setting; nullopt if it failed.
  HtmlFigure figure(const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow, std::optional<Image>* shadow_factor = nullptr) {
    return figure(renderer_, options_.light_choice, file, caption, render, shadow, shadow_factor);
  }
  // The same with another renderer, made for the scene with `light_choice`.
  HtmlFigure figure(Renderer& renderer, const std::string& light_choice, const std::string& file,
                    const std::string& caption, RenderSettings render, ShadowSettings shadow,
                    std::optional<Image>* shadow_factor = nullptr) {
    return figure(renderer, options_.scene_argument, options_.model_argument, light_choice, file,
                  caption, render, shadow, shadow_factor);
  }
  // The same for another scene, named by its --scene (or --model) argument.
  HtmlFigure figure(Renderer& renderer, const std::string& scene_argument,
                    const std::string& model_argument, const std::string& light_choice,
                    const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow, std::optional<Image>* shadow_factor = nullptr) {
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
    step();
    try {
      renderer.render(render, shadow);
      const Image image = renderer.read_view();
      check_gl();
      write_png(image, path_of(file), png_encoding_for(render.view));
      f.image = file;
      f.width = image.width;
      f.height = image.height;
    } catch (const std::exception& e) {
      f.error = e.what();
      f.command.clear();
      ++failed_;
    }
    if (shadow_factor != nullptr) {
      *shadow_factor = std::nullopt;
      if (f.error.empty()) *shadow_factor = shaded(renderer, View::Shadow);
    }
    return f;
  }

  // Another view of the frame the renderer made last (Renderer::shade).
  std::optional<Image> shaded(Renderer& renderer, View view) {
    try {
      renderer.shade(view);
      Image image = renderer.read_view();
      check_gl();
      return image;
    } catch (const std::exception&) {
      ++failed_;
      return std::nullopt;
    }
  }

  // An image the study computed (not rendered by one command) as a figure.
  HtmlFigure written_figure(const Image& image, const std::string& file, const std::string& caption,
                            PngEncoding encoding) {
    HtmlFigure f;
    f.caption = caption;
    try {
      write_png(image, path_of(file), encoding);
      f.image = file;
      f.width = image.width;
      f.height = image.height;
    } catch (const std::exception& e) {
      f.error = e.what();
      ++failed_;
    }
    return f;
  }

  std::string path_of(const std::string& file) const {
    return (std::filesystem::path(options_.output_dir) / file).string();
  }

  // Starts a section of the page, and the step of the progress it is.
  void section(HtmlPage& page, const std::string& id, const std::string& title) {
    page.section(id, title);
    progress_.step(title, items_, total_items());
  }

  // One item done; `weight` counts it as that many frames' worth of work,
  // so the time left is estimated from like units.
  void step(int weight = 1) {
    items_ += weight;
    progress_.update(items_, total_items());
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
  // A moment technique's soft shadows: its summed-area table, each
  // pixel's filter sized from a blocker search.
  ShadowSettings soft(Technique t) const {
    ShadowSettings s = with(t);
    s.filter = Filter::Sat;
    s.soft = true;
    s.blur = 1;
    return s;
  }

  // The traced reference of the spot light at the base settings (light
  // size included), traced once.
  const TracedReference* base_traced() {
    if (!traced_tried_) {
      traced_tried_ = true;
      step();
      try {
        traced_ = traced_reference(renderer_, base_render_, base_shadow_, traced_samples(),
                                   default_cache_dir());
        check_gl();
      } catch (const std::exception& e) {
        ++failed_;
        traced_error_ = e.what();
      }
    }
    return traced_ ? &*traced_ : nullptr;
  }
  int traced_samples() const { return (options_.quick ? kQuickSize : kFullSize).samples; }

  // What --quick changes, so that nobody takes its numbers for the full
  // study's (or the README's, which come from full-size runs).
  static std::string quick_banner() {
    const StudySize& q = kQuickSize;
    const StudySize& f = kFullSize;
    return "This is the quick report (--quick): frames of " + std::to_string(q.width) + "x" +
           std::to_string(q.height) + " instead of " + std::to_string(f.width) + "x" +
           std::to_string(f.height) + ", shadow maps of " + map_size_text(q.map_size) +
           " instead of " + map_size_text(f.map_size) + ", traced references of " +
           std::to_string(q.samples) + " rays per pixel instead of " + std::to_string(f.samples) +
           ", and shorter sweeps (fewer filter widths, techniques per light type and foliage "
           "techniques). Its errors and times differ from the full report's and from the "
           "README's, which are measured at full size: `penumbra report -o DIR` makes the full "
           "study.";
  }

  void techniques_section(HtmlPage& page) {
    section(page, "techniques", "1. The techniques side by side");
    page.paragraph(
        "The same scene, camera and lights for every technique: a spot light (front right) and a "
        "directional light (from the left). Filtered techniques use a Gaussian of radius W = 4 "
        "texels; the soft variants size their filter from a blocker search (PCSS, and the "
        "summed-area-table moment shadows). Each image is shown at its own size; at this size "
        "the techniques differ in a few pixels along the shadows' edges, which the error images "
        "of section 6 colour and section 7 enlarges 4x, every technique beside the traced "
        "reference:",
        "section 7, close-ups", "#closeups");
    std::vector<HtmlFigure> figures;
    for (Technique t : {Technique::None, Technique::Hard, Technique::Pcf, Technique::Pcss,
                        Technique::Backprojection, Technique::Vsm, Technique::Esm, Technique::Msm,
                        Technique::Msm16, Technique::Evsm2, Technique::Evsm4}) {
      std::optional<Image> shadow_factor;
      figures.push_back(figure("technique-" + name_of(t) + ".png", name_of(t), base_render_,
                               with(t), &shadow_factor));
      if (shadow_factor) technique_shadows_.emplace_back(t, std::move(*shadow_factor));
    }
    for (Technique t : {Technique::Vsm, Technique::Msm}) {
      figures.push_back(figure("technique-" + name_of(t) + "-soft.png",
                               name_of(t) + " --soft (SAT)", base_render_, soft(t)));
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
      std::vector<std::optional<Image>> shadows(techniques.size());
      for (std::size_t i = 0; i < techniques.size(); ++i) {
        const Technique t = techniques[i];
        figures.push_back(figure(renderer, choice, "light-" + choice + "-" + name_of(t) + ".png",
                                 choice + ", " + name_of(t), base_render_, with(t), &shadows[i]));
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
      const std::vector<double> rmse = measure_light_type(renderer, shadows, samples, rows);
      if (type == LightType::Directional) {
        for (std::size_t i = 0; i < techniques.size(); ++i) {
          if (rmse[i] >= 0.0)
            findings_.directional_rmse.push_back({name_of(techniques[i]), rmse[i]});
        }
      }
    }
    page.table(rows);
    page.figures(figures);
  }

  // Appends each technique's RMSE against the light's traced reference to
  // its row (one row per technique's shadow factor, after the header);
  // returns them (-1 where one failed).
  std::vector<double> measure_light_type(Renderer& renderer,
                                         const std::vector<std::optional<Image>>& shadows,
                                         int samples, std::vector<std::vector<std::string>>& rows) {
    step();
    std::optional<TracedReference> traced;
    try {
      traced = traced_reference(renderer, base_render_, base_shadow_, samples, default_cache_dir());
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

  void maps_section(HtmlPage& page) {
    section(page, "maps", "3. Shadow maps before and after the blur");
    page.paragraph(
        "The spot light's map as each technique stores it, as colour (moments z, z^2, z^3 in "
        "red, green, blue; msm16 shows its quantized channels), before and after a Gaussian of "
        "W = 8, each pair side by side. ESM is shown as log(map)/c + 1, in depth units (EVSM "
        "likewise, from its positive warp exp(c+ (2z - 1))): after the blur that is "
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
    page.figures(figures, 2);
  }

  void sweeps_section(HtmlPage& page) {
    section(page, "sweeps", "4. From anti-aliased to soft: filter widths and light sizes");
    page.paragraph(
        "W = 1 or 2 only anti-aliases the edge; W = 16 and 32 simulate a wide light. A fixed "
        "filter widens every penumbra alike, contact shadows included; PCSS widens them with "
        "the blocker-receiver distance (sharp at the box's foot, wide under the high slab).");
    const TracedReference* traced = base_traced();
    const std::vector<int> widths =
        options_.quick ? std::vector<int>{1, 4, 16} : std::vector<int>{1, 2, 4, 8, 16, 32};
    const std::vector<Technique> swept =
        options_.quick ? std::vector<Technique>{Technique::Msm}
                       : std::vector<Technique>{Technique::Msm, Technique::Vsm, Technique::Esm,
                                                Technique::Msm16};
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
        figures.push_back(figure("sweep-" + name_of(t) + "-w" + std::to_string(w) + ".png",
                                 name_of(t) + ", W = " + std::to_string(w), base_render_, s,
                                 &image));
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

  // PCSS at each light size, and every soft technique's error against the
  // traced reference of the same light size.
  void light_size_sweep(HtmlPage& page) {
    page.heading("Light sizes", 3);
    const std::vector<float> sizes = {0.0f, 0.25f, 0.5f, 1.0f, 2.0f};
    struct Soft {
      std::string name;
      ShadowSettings settings;
    };
    const std::vector<Soft> techniques = {{"pcss", with(Technique::Pcss)},
                                          {"vsm --soft", soft(Technique::Vsm)},
                                          {"msm --soft", soft(Technique::Msm)},
                                          {"hard (no penumbra)", with(Technique::Hard)}};
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
      figures.push_back(figure("sweep-pcss-light" + fixed(size, 2) + ".png",
                               "pcss, light size " + fixed(size, 2), base_render_, pcss,
                               &pcss_shadow));
      step();
      ShadowSettings light = base_shadow_;
      light.light_size = size;
      std::optional<TracedReference> sized;
      const TracedReference* traced = nullptr;
      if (size == base_shadow_.light_size) {
        traced = base_traced();
      } else {
        try {
          sized = traced_reference(renderer_, base_render_, light, traced_samples(),
                                   default_cache_dir());
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
  std::string point_light_floor(const EdgeErrors& e) const {
    const double share = e.compared > 0 ? double(e.wrong) / double(e.compared) : 0.0;
    return "Why every technique shows the same error at light size 0: the source is then a "
           "point, so the traced reference is 0 or 1 at every pixel, and the soft techniques' "
           "filters shrink to a single texel: each makes, in effect, the hard map's binary "
           "test. The hard test disagrees with the traced rays on " +
           std::to_string(e.wrong) + " of the " + std::to_string(e.compared) +
           " pixels compared (" + fixed(100.0 * share, 2) + " %), " +
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

  // The spot light's shadow factor against the filtered reference.
  std::optional<ShadowMetrics> measure_against_filtered(const ShadowSettings& shadow,
                                                        const std::optional<Image>& technique) {
    const Image* reference = filtered_reference(shadow);
    if (!technique || !reference) return std::nullopt;
    return compare_shadow(*technique, *reference);
  }

  // The filtered hard reference of a filterable technique's settings: the
  // depth map's tests averaged with the filter's kernel
  // (filtered_hard_reference in shaders/render/lighting.frag), which reads
  // neither the technique nor its constants (ESM's c), so the study renders
  // it once per kernel, map and bias.
  const Image* filtered_reference(const ShadowSettings& shadow) {
    ShadowSettings key = shadow;
    key.technique = Technique::Vsm;
    key.esm_c = ShadowSettings{}.esm_c;
    for (const auto& [settings, image] : filtered_references_) {
      if (settings.blur == key.blur && settings.filter == key.filter &&
          settings.map_size == key.map_size && settings.constant_bias == key.constant_bias &&
          settings.slope_bias == key.slope_bias && settings.normal_offset == key.normal_offset &&
          settings.max_slope == key.max_slope) {
        return &image;
      }
    }
    std::optional<Image> image = shadow_image(key, View::ShadowReference);
    if (!image) return nullptr;
    filtered_references_.emplace_back(key, std::move(*image));
    return &filtered_references_.back().second;
  }

  void esm_section(HtmlPage& page) {
    section(page, "esm", "5. The ESM exponent c");
    const std::vector<float> cs = {10.0f, 20.0f, 40.0f, 60.0f, 80.0f, kEsmMaxC};
    std::vector<HtmlFigure> figures;
    std::vector<std::vector<std::string>> rows = {
        {"c", "mean abs. error", "light leaking", "over-darkening", "max error"}};
    std::vector<EsmPoint> points;
    for (float c : cs) {
      ShadowSettings s = with(Technique::Esm);
      s.esm_c = c;
      std::optional<Image> image;
      figures.push_back(figure("esm-c" + fixed(c, 0) + ".png", "esm, c = " + fixed(c, 0),
                               base_render_, s, &image));
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
        "the reverse (reference > 0.9, technique < 0.7).");
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

  struct EsmPoint {
    float c;
    ShadowMetrics m;
  };

  // What the sweep of c shows, its best c named only when no other c
  // measures the same at the printed precision (a tie is called a tie).
  static std::string esm_discussion(const std::vector<EsmPoint>& points) {
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

  // A technique's shadow factor at with(t), as section 1 read it, or
  // rendered now.
  std::optional<Image> technique_shadow(Technique t) {
    for (auto& [technique, image] : technique_shadows_) {
      if (technique == t) return image;
    }
    return shadow_image(with(t));
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
    section(page, "errors", "6. Errors against the references");
    const int samples = traced_samples();
    const TracedReference* traced = base_traced();
    if (!traced) page.paragraph("The traced reference failed: " + traced_error_);
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
        "blue where too dark; the boxes mark the regions section 7 enlarges. The last row is not "
        "a single frame: hard shadows from N points spread over the source, weighted as the "
        "reference weighs them and averaged (`--accumulate N`), the converged result the "
        "single-frame techniques approximate. Map bytes: what the shadow lookup reads per "
        "shadow-map texel (the depth map, or the technique's representation).");
    std::vector<std::vector<std::string>> rows = {
        {"technique", "MAE traced", "RMSE traced", "leaking traced", "over-dark traced",
         "MAE filtered", "leaking filtered", "map bytes / texel"}};
    // One row: `label` names the setting, `stem` its files.
    const auto add_row = [&](const std::string& label, const std::string& stem,
                             const ShadowSettings& settings, bool single_frame,
                             std::optional<Image> image) {
      if (!image || !traced) {
        rows.push_back({label, "failed"});
        return;
      }
      const ShadowMetrics m = compare_shadow(*image, traced->image);
      std::vector<std::string> row = {label, fixed(m.mean_absolute_error, 4), fixed(m.rmse, 4),
                                      fixed(100.0 * m.leak_fraction, 3) + " %",
                                      fixed(100.0 * m.over_dark_fraction, 3) + " %"};
      const Image* reference =
          is_filterable(settings.technique) ? filtered_reference(settings) : nullptr;
      if (reference) {
        const ShadowMetrics f = compare_shadow(*image, *reference);
        row.push_back(fixed(f.mean_absolute_error, 4));
        row.push_back(fixed(100.0 * f.leak_fraction, 3) + " %");
      } else {
        row.push_back("");
        row.push_back("");
      }
      row.push_back(std::to_string(map_bytes_per_texel(settings.technique)));
      rows.push_back(row);
      errors_.push_back({label, stem, settings.technique, single_frame, m, std::move(*image)});
    };
    for (Technique t : {Technique::Hard, Technique::Pcf, Technique::Pcss, Technique::Backprojection,
                        Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      step();
      const ShadowSettings settings = with(t);
      add_row(name_of(t), name_of(t), settings, true, technique_shadow(t));
    }
    // The converged counterpart: hard shadows from N points of the source,
    // weighted as the reference weighs them (render/accumulation.hpp).
    step();
    ShadowSettings accumulated = with(Technique::Hard);
    accumulated.accumulate = options_.quick ? 8 : 64;
    const std::string label = "hard --accumulate " + std::to_string(accumulated.accumulate);
    try {
      RenderSettings r = base_render_;
      r.view = View::Shadow;
      Image image = render_accumulated(renderer_, r, accumulated);
      check_gl();
      add_row(label, "hard-accumulate", accumulated, false, std::move(image));
    } catch (const std::exception&) {
      ++failed_;
      add_row(label, "hard-accumulate", accumulated, false, std::nullopt);
    }
    page.table(rows);

    if (traced) {
      std::vector<const Image*> images;
      for (const MeasuredError& e : errors_) images.push_back(&e.image);
      try {
        regions_ = choose_crop_regions(traced->image, images, base_render_.width / 8,
                                       base_render_.height / 8);
      } catch (const std::exception& e) {
        ++failed_;
        page.paragraph(std::string("Choosing the close-up regions failed: ") + e.what());
      }
    }
    page.graphic(svg_error_color_bar(kErrorImageRange, "technique - traced reference"));
    std::vector<HtmlFigure> figures;
    for (const MeasuredError& e : errors_) {
      HtmlFigure f;
      try {
        f = written_figure(error_image(e.image, traced->image), "error-" + e.stem + ".png",
                           e.label + " minus traced", PngEncoding::Linear);
      } catch (const std::exception& error) {
        f.caption = e.label + " minus traced";
        f.error = error.what();
        ++failed_;
      }
      for (std::size_t i = 0; i < regions_.size(); ++i) {
        const CropRegion& r = regions_[i];
        f.overlays.push_back({std::to_string(i + 1), r.x, r.y, r.width, r.height});
      }
      figures.push_back(f);
    }
    page.figures(figures);
  }

  // Three regions of the spot light's shadow at 4x, nearest neighbour:
  // every technique beside the traced reference.
  void closeups_section(HtmlPage& page) {
    section(page, "closeups", "7. Close-ups at 4x");
    const TracedReference* traced = base_traced();
    if (!traced || regions_.empty()) {
      page.paragraph("No close-ups: the traced reference or the techniques' images failed.");
      return;
    }
    page.paragraph(
        "The spot light's shadow factor (white: lit) in three regions of the camera image, "
        "enlarged " +
        std::to_string(kCropScale) +
        "x with nearest-neighbour sampling, so every pixel shows. The regions are chosen from "
        "the images, by these rules, in this order, none overlapping an earlier one; the error "
        "images of section 6 mark them with their numbers. Click a close-up for the whole "
        "shadow-factor image it was cut from. Under each: the mean absolute error against the "
        "traced reference within the region.");
    std::vector<std::vector<std::string>> rule_rows = {{"region", "x", "y", "width", "height"}};
    for (std::size_t i = 0; i < regions_.size(); ++i) {
      const CropRegion& r = regions_[i];
      page.paragraph(std::to_string(i + 1) + ". " + r.name + ": " + r.rule + ".");
      rule_rows.push_back({std::to_string(i + 1) + ". " + r.name, std::to_string(r.x),
                           std::to_string(r.y), std::to_string(r.width), std::to_string(r.height)});
    }
    page.table(rule_rows);

    // The full-size images the crops come from.
    const std::string reference_file = "shadow-traced.png";
    written_figure(traced->image, reference_file, "", PngEncoding::Linear);
    for (const MeasuredError& e : errors_) {
      written_figure(e.image, "shadow-" + e.stem + ".png", "", PngEncoding::Linear);
    }
    std::vector<std::vector<std::string>> error_rows = {{"technique"}};
    for (const MeasuredError& e : errors_) error_rows.push_back({e.label});
    for (std::size_t i = 0; i < regions_.size(); ++i) {
      const CropRegion& r = regions_[i];
      error_rows.front().push_back("MAE " + r.name);
      page.heading(std::to_string(i + 1) + ". " + r.name + " (x " + std::to_string(r.x) + ", y " +
                       std::to_string(r.y) + ")",
                   3);
      std::vector<HtmlFigure> figures;
      figures.push_back(
          crop_figure(traced->image, r, "traced reference", "traced", reference_file));
      for (std::size_t t = 0; t < errors_.size(); ++t) {
        const MeasuredError& e = errors_[t];
        const double mae = region_error(e.image, traced->image, r);
        error_rows[t + 1].push_back(fixed(mae, 4));
        if (r.id == "contact-shadow" && e.single_frame) {
          findings_.contact_mae.push_back({e.label, mae});
        }
        figures.push_back(crop_figure(e.image, r, e.label + ": MAE " + fixed(mae, 4), e.stem,
                                      "shadow-" + e.stem + ".png"));
      }
      page.figures(figures);
    }
    page.heading("Mean absolute error in each region", 3);
    page.table(error_rows);
  }

  static constexpr int kCropScale = 4;

  HtmlFigure crop_figure(const Image& image, const CropRegion& region, const std::string& caption,
                         const std::string& stem, const std::string& source) {
    HtmlFigure f;
    try {
      f = written_figure(crop_nearest(image, region, kCropScale),
                         "crop-" + region.id + "-" + stem + ".png", caption, PngEncoding::Linear);
    } catch (const std::exception& e) {
      f.caption = caption;
      f.error = e.what();
      ++failed_;
    }
    f.link = source;
    f.css_class = "crop";
    f.data = {{"region", region.id},
              {"source", source},
              {"x", std::to_string(region.x)},
              {"y", std::to_string(region.y)},
              {"width", std::to_string(region.width)},
              {"height", std::to_string(region.height)},
              {"scale", std::to_string(kCropScale)}};
    return f;
  }

  // Mean |technique - reference| over the region's compared pixels.
  static double region_error(const Image& technique, const Image& reference, const CropRegion& r) {
    double sum = 0.0;
    long count = 0;
    for (int y = r.y; y < r.y + r.height; ++y) {
      for (int x = r.x; x < r.x + r.width; ++x) {
        const float* t = technique.pixel(x, y);
        const float* f = reference.pixel(x, y);
        if (t[3] < 0.5f || f[3] < 0.5f) continue;
        sum += std::abs(double(t[0]) - double(f[0]));
        ++count;
      }
    }
    return count > 0 ? sum / static_cast<double>(count) : 0.0;
  }

  // Alpha-tested casters: the foliage scene (report/foliage_scene.hpp),
  // each technique against the traced reference of each of its lights.
  void foliage_section(HtmlPage& page) {
    section(page, "foliage", "8. Foliage: alpha-tested casters");
    const int samples = traced_samples();
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
      step();
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
        step();
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
      if (!measured.empty()) {
        summary.push_back(foliage_summary(light_name, measured));
        // The verdict's foliage line: the first light's closest technique.
        if (!findings_.foliage) {
          const auto best =
              std::min_element(measured.begin(), measured.end(),
                               [](auto& a, auto& b) { return a.second.rmse < b.second.rmse; });
          findings_.foliage = VerdictLine{
              "Foliage and other alpha-tested casters",
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
    page.graphic(svg_error_color_bar(kErrorImageRange, "technique - traced reference"));
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
    section(page, "timings", "9. GPU time and memory traffic per pass");
    const bool timer = !timers_miss_compute(context_.renderer());
    page.paragraph(
        "Device: " + context_.renderer() + " (" + context_.vendor() + ", " + context_.version() +
        "). Median of " + std::to_string(kTimedFrames) + " frames at " +
        std::to_string(base_render_.width) + "x" + std::to_string(base_render_.height) +
        " with a " + std::to_string(base_shadow_.map_size) + "^2 map, passes serialized, in ms (" +
        (timer ? "GPU timer queries"
               : "wall clock: this renderer's timer queries miss compute work") +
        "). The last column puts each filter pass against a compute copy of the same map (one "
        "read, one write per texel): the filters are memory-bound, so that ratio says how close "
        "they come to the bandwidth limit. `penumbra bench` measures more. Passes no technique "
        "ran are left out." +
        (is_software_renderer(context_.renderer())
             ? " This renderer emulates the GPU on the CPU: its times rank the techniques' "
               "work, not what a GPU would take."
             : ""));
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> header = {"technique"};
    for (std::size_t p = 0; p < kPassCount; ++p) header.emplace_back(gl::kGpuPassNames[p]);
    header.emplace_back("total");
    header.emplace_back("filters / copy");
    rows.push_back(header);
    for (Technique t : {Technique::Hard, Technique::Pcf, Technique::Pcss, Technique::Backprojection,
                        Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      // Its frames, each with the copy yardstick: about eight frames' work.
      step(2 * (kTimedFrames + 1));
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
        const double total = spread_of(timer ? times.total.timer_ms : times.total.wall_ms).median;
        row.push_back(fixed(total, 2));
        total_ms_.push_back({name_of(t), total});
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
    quality_cost_plot(page);
    traffic_plot(page);
  }

  // RMSE against GPU time, one point per technique timed and measured; the
  // settings no other beats in both marked as the Pareto front.
  void quality_cost_plot(HtmlPage& page) {
    std::vector<std::string> names;
    std::vector<CostQuality> points;
    for (const auto& [name, ms] : total_ms_) {
      for (const MeasuredError& e : errors_) {
        if (e.label != name) continue;
        names.push_back(name);
        points.push_back({ms, e.traced.rmse});
      }
    }
    const std::vector<std::size_t> front = pareto_front(points);
    const bool emulated = is_software_renderer(context_.renderer());
    LinePlot plot{.title = "Quality against cost",
                  .x = {emulated ? "frame time on a GPU emulated on the CPU (ms, the table's "
                                   "total; not a GPU ranking)"
                                 : "GPU time per frame (ms, the table's total)",
                        false},
                  .y = {kRmseLabel, false},
                  .series = {{"technique (W = 4)", {}, false}},
                  .highlight_name = "Pareto front"};
    std::vector<std::vector<std::string>> data = {
        {"technique", "time (ms)", "RMSE traced", "on the Pareto front"}};
    for (std::size_t i = 0; i < points.size(); ++i) {
      const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
      plot.series[0].points.push_back({points[i].cost, points[i].error, names[i], on_front});
      data.push_back(
          {names[i], fixed(points[i].cost, 2), fixed(points[i].error, 4), on_front ? "yes" : "no"});
      if (on_front) findings_.pareto.push_back({names[i], {points[i].cost, points[i].error}});
    }
    page.heading("Quality against cost", 3);
    page.paragraph(
        "Each technique's RMSE against the traced reference (section 6) against its frame time "
        "(the table above). Filled points are the Pareto front: no other technique is both "
        "faster and closer to the reference." +
        std::string(emulated ? " These times are CPU emulation, not a GPU ranking: on this "
                               "renderer every pass runs on the CPU, where arithmetic costs "
                               "what memory traffic costs on a GPU, so the order of the "
                               "techniques can differ on real hardware."
                             : ""));
    page.plot(svg_line_plot(plot), data);
  }

  // The bytes each pass over the shadow-map array moves per texel, from the
  // passes' own formats, tiles and aprons (the accounting `penumbra bench`
  // divides by the measured time).
  void traffic_plot(HtmlPage& page) {
    struct Setting {
      std::string name;
      ShadowSettings shadow;
    };
    std::vector<Setting> settings;
    for (Technique t : {Technique::Vsm, Technique::Esm, Technique::Msm, Technique::Msm16,
                        Technique::Evsm2, Technique::Evsm4}) {
      settings.push_back({name_of(t), with(t)});
    }
    settings.push_back({"vsm --soft", soft(Technique::Vsm)});
    settings.push_back({"msm --soft", soft(Technique::Msm)});
    const int size = base_shadow_.map_size;
    std::vector<std::array<std::optional<TexelTraffic>, kPassCount>> traffic;
    std::array<bool, kPassCount> used{};
    for (const Setting& s : settings) {
      traffic.push_back(shadow_map_traffic(s.shadow, size, size));
      for (std::size_t p = 0; p < kPassCount; ++p) used[p] = used[p] || traffic.back()[p];
    }
    // The copy is the yardstick the table compares with, not a pass of the
    // techniques.
    used[static_cast<std::size_t>(gl::GpuPass::BandwidthCopy)] = false;
    StackedBars bars{.title = "Memory traffic per shadow-map texel",
                     .value_label = "bytes read + written per texel",
                     .categories = {},
                     .stack_names = {},
                     .values = {}};
    std::vector<std::vector<std::string>> data = {{"setting", "map bytes / texel"}};
    for (std::size_t p = 0; p < kPassCount; ++p) {
      if (!used[p]) continue;
      bars.stack_names.emplace_back(gl::kGpuPassNames[p]);
      data.front().push_back(std::string(gl::kGpuPassNames[p]) + " (read + written)");
    }
    data.front().emplace_back("total");
    for (std::size_t i = 0; i < settings.size(); ++i) {
      bars.categories.push_back(settings[i].name);
      bars.values.emplace_back();
      std::vector<std::string> row = {
          settings[i].name, std::to_string(map_bytes_per_texel(settings[i].shadow.technique))};
      double total = 0.0;
      for (std::size_t p = 0; p < kPassCount; ++p) {
        if (!used[p]) continue;
        const double bytes = traffic[i][p] ? traffic[i][p]->total() : 0.0;
        bars.values.back().push_back(bytes);
        total += bytes;
        row.push_back(traffic[i][p] ? plot_number(traffic[i][p]->read) + " + " +
                                          plot_number(traffic[i][p]->written)
                                    : "");
      }
      row.push_back(plot_number(total));
      data.push_back(row);
    }
    page.heading("Bytes per texel per pass", 3);
    page.paragraph(
        "The bytes each pass over the " + std::to_string(size) +
        "^2 shadow-map array reads and "
        "writes per texel, counted from its formats, tiles and aprons, every texel a workgroup "
        "loads taken as a read from memory (include/penumbra/shadow/texel_traffic.hpp). On a GPU "
        "the filters "
        "are memory-bound, so these bytes set their cost. The depth-testing techniques (hard, "
        "pcf, pcss) run no pass over the map after the depth pass.");
    page.plot(svg_stacked_bars(bars), data);
  }

  // The page's first section: which technique when, each from a number this
  // run measured, linked to the section that shows it.
  void verdict(HtmlPage& page) {
    findings_.light_size = base_shadow_.light_size;
    findings_.cascades = base_shadow_.cascades;
    findings_.software_times = is_software_renderer(context_.renderer());
    for (const MeasuredError& e : errors_) {
      if (!e.single_frame) continue;
      findings_.rmse.push_back({e.label, e.traced.rmse});
      findings_.map_bytes.push_back(map_bytes_per_texel(e.technique));
    }
    std::string intro =
        "Which technique to use when, from this run's measurements on scene '" + scene_.name +
        "'. Each line gives the number it rests on and links to the section that shows it; "
        "values equal at the printed precision are ties.";
    if (!findings_.foliage) {
      intro += " This report has no foliage section, so foliage gets no verdict.";
    }
    page.verdict("Summary: which technique when", intro, verdict_lines(findings_));
  }

  static constexpr int kTimedFrames = 3;

  const Scene& scene_;
  StudyOptions options_;
  gl::Context& context_;
  Renderer renderer_;
  RenderSettings base_render_;
  ShadowSettings base_shadow_;
  // The traced reference at the base settings, once.
  std::optional<TracedReference> traced_;
  bool traced_tried_ = false;
  std::string traced_error_;
  std::vector<MeasuredError> errors_;
  std::vector<CropRegion> regions_;
  std::vector<std::pair<std::string, double>> total_ms_;
  std::list<std::pair<ShadowSettings, Image>> filtered_references_;
  std::vector<std::pair<Technique, Image>> technique_shadows_;  // section 1's, at with(t)
  // What the verdict is drawn from (a foliage section sets its line).
  StudyFindings findings_;
  // Images, metrics and timings the study makes, weighted as step() weighs
  // them, for the progress bar (the report test checks the --quick count).
  int total_items() const { return options_.quick ? 204 : 274; }
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
