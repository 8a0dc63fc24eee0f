#pragma once
// One run of the study (report/study.hpp): what its sections share (the
// scene's renderer, the base settings, the traced reference, the images
// and numbers one section measures and a later one reads, the progress)
// and the helpers that render and record a figure. Each section is
// written by its own file under report/sections/, in the page's order.
#include <atomic>
#include <exception>
#include <list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/number_text.hpp"
#include "io/image.hpp"
#include "io/png_writer.hpp"
#include "io/progress_bar.hpp"
#include "penumbra/gl/context.hpp"
#include "penumbra/settings.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "report/crop_regions.hpp"
#include "report/edge_errors.hpp"
#include "report/html_page.hpp"
#include "report/study.hpp"
#include "report/verdict.hpp"
#include "scene/scene.hpp"

namespace penumbra {

std::string name_of(Technique t);
// Bytes per texel of the map a technique's lookup reads: the depth map for
// the techniques that test depths, the representation for the others.
int map_bytes_per_texel(Technique t);
std::string map_size_text(int size);

// One technique's (or setting's) errors against the traced reference.
struct MeasuredError {
  std::string label;  // as the tables name it
  std::string stem;   // its files: shadow-STEM.png, error-STEM.png
  Technique technique = Technique::Hard;
  bool single_frame = true;  // false for --accumulate
  ShadowMetrics traced;
  Image image;  // the spot light's shadow factor
};

inline constexpr const char* kRmseLabel = "RMSE against the traced reference (shadow factor)";

// The sizes a study renders and traces at: the full study's, or --quick's.
struct StudySize {
  int width, height;  // of every frame
  int map_size;       // of every shadow map but section 3's
  int samples;        // rays per pixel of the traced references
};
inline constexpr StudySize kFullSize{640, 360, 2048, 256};
// --quick: a 512^2 map still has a texel per pixel or more across the
// spot light's cone at 320x180, for a quarter of the filters' work.
inline constexpr StudySize kQuickSize{320, 180, 512, 64};
// A rehearsal's (report/shader_rehearsal.hpp): llvmpipe compiles a shader
// variant per state of what it draws with, including whether each
// texture's and target's sides are powers of two, but not their sizes; so
// the frame's sides, like the study's, are not powers of two, and the maps'
// are.
inline constexpr StudySize kRehearsalSize{96, 54, 128, 1};

// A study makes the report, or rehearses it: every frame and dispatch of
// the report in the same order and state, at kRehearsalSize, writing no
// image, tracing its references with a ray a pixel and caching none.
enum class StudyMode { Report, Rehearsal };
struct StudyStopped : std::exception {
  [[nodiscard]] const char* what() const noexcept override { return "the study was stopped"; }
};

// Calls render(0) with `renderer` lit by its light `light` alone, as its
// light 0, and gives the renderer its lights back after. One light's
// shadow factor (the shadow and shadow-reference views) reads that light's
// maps alone, and a light's views are fitted without the others, so the
// image is the one the whole scene's frame gives for that light; but the
// other lights' maps (a sun's cascades, a point light's six faces) are
// neither rendered nor filtered: on a GPU emulated on the CPU the filters
// are most of a frame.
template <class Render>
auto with_light_alone(Renderer& renderer, int light, Render&& render) {
  const std::vector<Light> lights = renderer.scene().lights;
  if (lights.size() <= 1 || light < 0 || static_cast<std::size_t>(light) >= lights.size()) {
    return render(light);
  }
  struct Restore {
    Renderer& renderer;
    const std::vector<Light>& lights;
    ~Restore() { renderer.set_lights(lights); }
  } restore{renderer, lights};
  renderer.set_lights({lights[static_cast<std::size_t>(light)]});
  return render(0);
}

// Lights `renderer` with `lights` until the end of the scope, then gives
// it back the lights it had.
class ScopedLights {
 public:
  ScopedLights(Renderer& renderer, const std::vector<Light>& lights)
      : renderer_(renderer), saved_(renderer.scene().lights) {
    renderer.set_lights(lights);
  }
  ~ScopedLights() { renderer_.set_lights(saved_); }
  ScopedLights(const ScopedLights&) = delete;
  ScopedLights& operator=(const ScopedLights&) = delete;

 private:
  Renderer& renderer_;
  std::vector<Light> saved_;
};

class Study {
 public:
  // A rehearsal stops at its next section once `stop` is set (throwing
  // StudyStopped out of run()).
  Study(const Scene& scene, const StudyOptions& options, gl::Context& context,
        StudyMode mode = StudyMode::Report, const std::atomic<bool>* stop = nullptr);
  StudyResult run();

 private:
  // The sections, one file each (report/sections/NAME.cpp), and the items
  // each makes, weighted as step() weighs them: their sum is the progress
  // bar's total, counted from the same lists the sections loop over.
  void techniques_section(HtmlPage& page);  // 1
  [[nodiscard]] int techniques_items() const;
  void light_types_section(HtmlPage& page);  // 2
  [[nodiscard]] int light_types_items() const;
  void maps_section(HtmlPage& page);  // 3
  [[nodiscard]] int maps_items() const;
  void sweeps_section(HtmlPage& page);  // 4, filter widths, then light_size_sweep
  [[nodiscard]] int sweeps_items() const;
  void light_size_sweep(HtmlPage& page);
  [[nodiscard]] int light_size_items() const;
  void esm_section(HtmlPage& page);  // 5
  [[nodiscard]] int esm_items() const;
  void errors_section(HtmlPage& page);  // 6
  [[nodiscard]] int errors_items() const;
  void closeups_section(HtmlPage& page);  // 7
  void foliage_section(HtmlPage& page);   // 8
  [[nodiscard]] int foliage_items() const;
  void timings_section(HtmlPage& page);  // 9
  [[nodiscard]] int timings_items() const;
  void texel_density_section(HtmlPage& page);  // 10
  [[nodiscard]] int texel_density_items() const;
  void verdict(HtmlPage& page);

  // Section helpers that read the study's state.
  std::vector<double> measure_light_type(const std::vector<std::optional<Image>>& shadows,
                                         std::vector<std::vector<std::string>>& rows);
  [[nodiscard]] std::string point_light_floor(const EdgeErrors& e) const;
  HtmlFigure crop_figure(const Image& image, const CropRegion& region, const std::string& caption,
                         const std::string& stem, const std::string& source);
  void quality_cost_plot(HtmlPage& page);
  void traffic_plot(HtmlPage& page);
  // A foliage technique's image measured against its light's reference.
  struct FoliageMeasure {
    double rmse = 0.0;
    double total_shadow = 0.0;  // its shadow over the reference's
  };
  void foliage_map_sizes(
      HtmlPage& page, Renderer& renderer, const std::vector<Technique>& techniques,
      const std::vector<std::optional<TracedReference>>& traced,
      const std::vector<std::vector<std::optional<FoliageMeasure>>>& base_measures);

  // Renders one image into the report folder, or records why it failed.
  // With `shadow_factor`, also the spot light's shadow factor of the same
  // frame (Renderer::shade: its maps are not rendered again), for the
  // measurements of the same setting; nullopt if it failed.
  HtmlFigure figure(const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow, std::optional<Image>* shadow_factor = nullptr);
  // The same with another renderer, made for the scene with `light_choice`.
  HtmlFigure figure(Renderer& renderer, const std::string& light_choice, const std::string& file,
                    const std::string& caption, RenderSettings render, ShadowSettings shadow,
                    std::optional<Image>* shadow_factor = nullptr);
  // The same for another scene, named by its --scene (or --model) argument.
  HtmlFigure figure(Renderer& renderer, const std::string& scene_argument,
                    const std::string& model_argument, const std::string& light_choice,
                    const std::string& file, const std::string& caption, RenderSettings render,
                    ShadowSettings shadow, std::optional<Image>* shadow_factor = nullptr);
  // Another view of the frame the renderer made last (Renderer::shade).
  std::optional<Image> shaded(Renderer& renderer, View view);
  // An image the study computed (not rendered by one command) as a figure.
  HtmlFigure written_figure(const Image& image, const std::string& file, const std::string& caption,
                            PngEncoding encoding);
  [[nodiscard]] std::string path_of(const std::string& file) const;
  // The settings a frame of `shadow` is drawn with: `shadow`, or in a
  // rehearsal its maps no larger than kRehearsalSize's.
  [[nodiscard]] ShadowSettings drawn(ShadowSettings shadow) const;
  // Writes `image` as the report's `file` (a rehearsal writes nothing).
  void write_report_png(const Image& image, const std::string& file, PngEncoding encoding);
  // The traced reference of `renderer`'s frame for `render` and `shadow`,
  // at the study's rays per pixel, from the reference cache or traced and
  // stored there.
  TracedReference trace(Renderer& renderer, const RenderSettings& render,
                        const ShadowSettings& shadow);
  [[nodiscard]] bool rehearsal() const { return mode_ == StudyMode::Rehearsal; }
  [[nodiscard]] const StudySize& size() const {
    return rehearsal() ? kRehearsalSize : options_.quick ? kQuickSize : kFullSize;
  }
  // Starts a section of the page, and the step of the progress it is.
  void section(HtmlPage& page, const std::string& id, const std::string& title);
  // One item done; `weight` counts it as that many frames' worth of work,
  // so the time left is estimated from like units.
  void step(int weight = 1);
  void check_gl();
  // The image `make` returns, with GL checked after it; a failure is
  // counted in the study's failures (the page says how many) and gives no
  // image, instead of ending the study.
  template <class Make>
  std::optional<Image> image_or_failure(Make&& make) {
    try {
      Image image = make();
      check_gl();
      return image;
    } catch (const std::exception&) {
      ++failed_;
      return std::nullopt;
    }
  }
  [[nodiscard]] ShadowSettings with(Technique t) const;
  // A moment technique's soft shadows: its summed-area table, each
  // pixel's filter sized from a blocker search.
  [[nodiscard]] ShadowSettings soft(Technique t) const;
  // The traced reference of the spot light at the base settings (light
  // size included), traced once (one item, the first time).
  const TracedReference* base_traced();
  // The light the study measures (base_render_.light_index) alone: the
  // --light choice that lights the scene with it alone (the study's own
  // when the scene has no other light) and the lights that choice gives.
  // The sweeps measure that light's shadow factor and show its frames: the
  // other lights' maps (a sun's cascades) would be filtered again at every
  // setting for images no number reads.
  struct LightAlone {
    std::string choice;
    std::vector<Light> lights;
  };
  const LightAlone& measured_light_alone();
  [[nodiscard]] int traced_samples() const { return size().samples; }
  // The spot light's shadow factor against the filtered reference.
  std::optional<ShadowMetrics> measure_against_filtered(const ShadowSettings& shadow,
                                                        const std::optional<Image>& technique);
  // The filtered hard reference of a filterable technique's settings: the
  // depth map's tests averaged with the filter's kernel
  // (filtered_hard_reference in shaders/render/lighting.frag), which reads
  // neither the technique nor its constants (ESM's c), so the study renders
  // it once per kernel, map and bias.
  const Image* filtered_reference(const ShadowSettings& shadow);
  // A technique's shadow factor at with(t), as section 1 read it, or
  // rendered now.
  std::optional<Image> technique_shadow(Technique t);
  // The spot light's shadow factor of a technique, or nullopt on failure.
  std::optional<Image> shadow_image(const ShadowSettings& shadow, View view = View::Shadow);
  std::optional<Image> shadow_image(Renderer& renderer, const RenderSettings& render,
                                    const ShadowSettings& shadow, View view = View::Shadow);
  [[nodiscard]] int total_items() const;

  const Scene& scene_;
  StudyOptions options_;
  gl::Context& context_;
  StudyMode mode_;
  const std::atomic<bool>* stop_;
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
  std::optional<LightAlone> light_alone_;
  // The foliage scene (section 8), once written and read.
  std::optional<Scene> foliage_scene_;
  // What the verdict is drawn from (a foliage section sets its line).
  StudyFindings findings_;
  std::optional<ProgressBar> progress_;            // none in a rehearsal
  std::optional<BackgroundPngWriter> png_writer_;  // none in a rehearsal
  int items_ = 0;
  int failed_ = 0;
  int errors_seen_ = 0;
};

}  // namespace penumbra
