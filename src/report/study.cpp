#include "report/study.hpp"

#include <filesystem>

#include "io/atomic_file.hpp"
#include "render/pass_timing.hpp"
#include "report/shader_rehearsal.hpp"
#include "report/study_run.hpp"

namespace penumbra {

namespace {

// What --quick changes, so that nobody takes its numbers for the full
// study's (or the README's, which come from full-size runs).
std::string quick_banner() {
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

}  // namespace

Study::Study(const Scene& scene, const StudyOptions& options, gl::Context& context, StudyMode mode,
             const std::atomic<bool>* stop)
    : scene_(scene),
      options_(options),
      context_(context),
      mode_(mode),
      stop_(stop),
      renderer_(scene) {
  base_render_.width = size().width;
  base_render_.height = size().height;
  base_shadow_.map_size = size().map_size;
  if (!rehearsal()) {
    progress_.emplace("report");
    png_writer_.emplace();
  }
}

int Study::total_items() const {
  return techniques_items() + light_types_items() + maps_items() + sweeps_items() + esm_items() +
         errors_items() + foliage_items() + timings_items() + texel_density_items();
}

StudyResult Study::run() {
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
  // Compiling shaders is most of what llvmpipe does on this thread: a
  // rehearsal on another compiles them ahead (report/shader_rehearsal.hpp).
  std::optional<ShaderRehearsal> rehearsed;
  if (!rehearsal() && ShaderRehearsal::helps(context_))
    rehearsed.emplace(scene_, options_, context_);
  techniques_section(page);
  light_types_section(page);
  maps_section(page);
  sweeps_section(page);
  esm_section(page);
  errors_section(page);
  closeups_section(page);
  foliage_section(page);
  // The timings measure this thread's passes alone.
  rehearsed.reset();
  if (png_writer_) png_writer_->finish();
  timings_section(page);
  texel_density_section(page);
  if (progress_) progress_->step("the verdict and the page", items_, total_items());
  verdict(page);

  StudyResult result;
  result.index_path = (std::filesystem::path(options_.output_dir) / "index.html").string();
  if (png_writer_) png_writer_->finish();
  if (!rehearsal()) write_file_atomically(result.index_path, page.finish());
  if (progress_) progress_->finish();
  result.items = items_;
  result.failed = failed_;
  return result;
}

// The page's first section: which technique when, each from a number this
// run measured, linked to the section that shows it.
void Study::verdict(HtmlPage& page) {
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

StudyResult write_study(const Scene& scene, const StudyOptions& options, gl::Context& context) {
  std::filesystem::create_directories(options.output_dir);
  return Study(scene, options, context).run();
}

}  // namespace penumbra
