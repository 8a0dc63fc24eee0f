#include "report/study_run.hpp"

#include <cmath>
namespace penumbra {

namespace {

constexpr int kCropScale = 4;

// Mean |technique - reference| over the region's compared pixels.
double region_error(const Image& technique, const Image& reference, const CropRegion& r) {
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

}  // namespace

// Three regions of the spot light's shadow at 4x, nearest neighbour:
// every technique beside the traced reference.
void Study::closeups_section(HtmlPage& page) {
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
    figures.push_back(crop_figure(traced->image, r, "traced reference", "traced", reference_file));
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

HtmlFigure Study::crop_figure(const Image& image, const CropRegion& region,
                              const std::string& caption, const std::string& stem,
                              const std::string& source) {
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

}  // namespace penumbra
