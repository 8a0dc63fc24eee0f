#pragma once
// Where the report zooms in: three regions of the camera image, chosen from
// the techniques' errors against the traced reference and from the
// reference's own penumbrae, and their nearest-neighbour enlargements.
#include <string>
#include <vector>

#include "io/image.hpp"

namespace penumbra {

struct CropRegion {
  std::string id;                           // "largest-error", "contact-shadow", "wide-penumbra"
  std::string name;                         // as the page titles it
  std::string rule;                         // how it was chosen, as the page states it
  int x = 0, y = 0, width = 0, height = 0;  // pixels of the camera image
  double score = 0.0;                       // what the rule maximized
};

// Penumbra steeper than this (shadow factor per pixel) counts as a sharp,
// contact edge: the light goes from lit to shadowed within 4 pixels.
inline constexpr float kSharpEdgeSlope = 0.25f;
// A reference value strictly between these is inside a penumbra.
inline constexpr float kPenumbraLow = 0.1f, kPenumbraHigh = 0.9f;

// Three width x height windows of the reference's size, in this order and
// none overlapping an earlier one (each the best window left), over the
// compared pixels (alpha 1 in the reference and in every technique):
//  largest error   the most summed |technique - reference| over all the
//                  techniques;
//  contact shadow  the most pixels where the reference's slope (the larger
//                  central difference, x or y) is at least kSharpEdgeSlope:
//                  the sharp edges a blocker touching its receiver casts;
//  wide penumbra   the most pixels whose reference lies strictly between
//                  kPenumbraLow and kPenumbraHigh and is not sharp: wide
//                  soft edges, where a blocker is far from its receiver.
// Ties go to the window first in reading order. Throws RuntimeError when an
// image's size differs from the reference's or the window does not fit.
std::vector<CropRegion> choose_crop_regions(const Image& reference,
                                            const std::vector<const Image*>& techniques, int width,
                                            int height);

// The region enlarged `scale` times, each pixel repeated scale x scale.
Image crop_nearest(const Image& image, const CropRegion& region, int scale);

}  // namespace penumbra
