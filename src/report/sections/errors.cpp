#include "report/study_run.hpp"

#include <iterator>

#include "reference/error_image.hpp"
#include "render/accumulation.hpp"
#include "report/svg_plot.hpp"

namespace penumbra {

namespace {

constexpr Technique kErrorTechniques[] = {
    Technique::Hard, Technique::Pcf, Technique::Pcss,  Technique::Backprojection, Technique::Vsm,
    Technique::Esm,  Technique::Msm, Technique::Msm16, Technique::Evsm2,          Technique::Evsm4};

}  // namespace

// A measurement per technique, backprojection's with contact shadows, and
// the accumulated hard shadows'.
int Study::errors_items() const {
  return static_cast<int>(std::size(kErrorTechniques)) + 2;
}

void Study::errors_section(HtmlPage& page) {
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
  for (Technique t : kErrorTechniques) {
    step();
    const ShadowSettings settings = with(t);
    add_row(name_of(t), name_of(t), settings, true, technique_shadow(t));
  }
  // The best single frame with screen-space contact shadows
  // (docs/rendering.md, --contact-shadows).
  step();
  ShadowSettings contact = with(Technique::Backprojection);
  contact.contact_shadows = true;
  add_row("backprojection --contact-shadows", "backprojection-contact", contact, true,
          shadow_image(contact));
  // The converged counterpart: hard shadows from N points of the source,
  // weighted as the reference weighs them (render/accumulation.hpp).
  step();
  ShadowSettings accumulated = with(Technique::Hard);
  accumulated.accumulate = options_.quick ? 8 : 64;
  const std::string label = "hard --accumulate " + std::to_string(accumulated.accumulate);
  std::optional<Image> image = image_or_failure([&] {
    RenderSettings r = base_render_;
    r.view = View::Shadow;
    return with_light_alone(renderer_, r.light_index, [&](int light) {
      r.light_index = light;
      return render_accumulated(renderer_, r, accumulated);
    });
  });
  add_row(label, "hard-accumulate", accumulated, false, std::move(image));
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

}  // namespace penumbra
