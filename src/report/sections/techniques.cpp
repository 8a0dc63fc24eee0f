#include "report/study_run.hpp"

#include <algorithm>
#include <iterator>

namespace penumbra {

namespace {

// Every technique, then the moment techniques' soft shadows.
constexpr Technique kTechniques[] = {
    Technique::None,           Technique::Hard,  Technique::Pcf,  Technique::Pcss,
    Technique::Backprojection, Technique::Vsm,   Technique::Esm,  Technique::Msm,
    Technique::Msm16,          Technique::Evsm2, Technique::Evsm4};
constexpr Technique kSoftTechniques[] = {Technique::Vsm, Technique::Msm};

}  // namespace

// A figure each, and the ambient-occlusion buffer's.
int Study::techniques_items() const {
  return static_cast<int>(std::size(kTechniques) + std::size(kSoftTechniques)) + 1;
}

void Study::techniques_section(HtmlPage& page) {
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
  // Each technique makes its own filtered maps: kept, every format's
  // arrays for both lights would add up (msm's, evsm4's and the soft
  // shadows' summed-area tables, a cascade each of the sun's).
  const auto plain = [&](Technique t) {
    renderer_.release_filtered_maps();
    std::optional<Image> shadow_factor;
    figures.push_back(figure("technique-" + name_of(t) + ".png", name_of(t), base_render_, with(t),
                             &shadow_factor));
    if (shadow_factor) technique_shadows_.emplace_back(t, std::move(*shadow_factor));
  };
  const auto soft_shadows = [&](Technique t) {
    renderer_.release_filtered_maps();
    figures.push_back(figure("technique-" + name_of(t) + "-soft.png", name_of(t) + " --soft (SAT)",
                             base_render_, soft(t)));
  };
  if (rehearsal()) {
    // From the other end (report/shader_rehearsal.hpp).
    std::for_each(std::rbegin(kSoftTechniques), std::rend(kSoftTechniques), soft_shadows);
    std::for_each(std::rbegin(kTechniques), std::rend(kTechniques), plain);
  } else {
    std::for_each(std::begin(kTechniques), std::end(kTechniques), plain);
    std::for_each(std::begin(kSoftTechniques), std::end(kSoftTechniques), soft_shadows);
  }
  RenderSettings ao = base_render_;
  ao.view = View::Ao;
  figures.push_back(figure("ambient-occlusion.png",
                           "the ambient-occlusion buffer (SSAO), which scales the ambient term", ao,
                           base_shadow_));
  page.figures(figures);
}

}  // namespace penumbra
