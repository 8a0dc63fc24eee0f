#include "report/study_run.hpp"

#include <iterator>

namespace penumbra {

namespace {

constexpr Technique kMapTechniques[] = {Technique::Vsm,   Technique::Esm,   Technique::Msm,
                                        Technique::Msm16, Technique::Evsm2, Technique::Evsm4};

}  // namespace

// Two figures per technique: its map before and after the blur.
int Study::maps_items() const {
  return 2 * static_cast<int>(std::size(kMapTechniques));
}

void Study::maps_section(HtmlPage& page) {
  section(page, "maps", "3. Shadow maps before and after the blur");
  page.paragraph(
      "The spot light's map as each technique stores it, as colour (moments z, z^2, z^3 in "
      "red, green, blue; msm16 shows its quantized channels), before and after a Gaussian of "
      "W = 8, each pair side by side. ESM is shown as log(map)/c + 1, in depth units (EVSM "
      "likewise, from its positive warp exp(c+ (2z - 1))): after the blur that is "
      "log(blur(exp(c z)))/c + 1, which is not blur(z): the exponential weights the farthest "
      "depths most, so edges move towards the far side.");
  std::vector<HtmlFigure> figures;
  for (Technique t : kMapTechniques) {
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

}  // namespace penumbra
