#pragma once
// Where a shadow factor disagrees with its reference outright: the pixels
// off by more than a half, and how many of them lie at the reference's
// shadow edges. With a point light both images are 0 or 1 at nearly every
// pixel, so these pixels are the whole of the error: each costs 1, and the
// RMSE is the square root of their share of the pixels compared.
#include "io/image.hpp"

namespace penumbra {

struct EdgeErrors {
  long compared = 0;   // pixels compared (alpha 1 in both images)
  long wrong = 0;      // of them, off by more than 0.5
  long near_edge = 0;  // of those, within `reach` pixels of a reference edge
};

// Counts over the red channels of two images of one size (alpha >= 0.5
// where compared); a reference edge is a compared neighbour whose value
// differs from the pixel's own by more than 0.5. Throws RuntimeError if
// the sizes differ.
EdgeErrors edge_errors(const Image& technique, const Image& reference, int reach);

// `technique` with only its pixels within `reach` pixels of a reference
// edge compared (alpha 0 elsewhere), an edge as above: compare_shadow() of
// it against the reference measures the error where shadows begin (where
// a map's texels alias). Throws RuntimeError if the sizes differ.
Image at_reference_edges(const Image& technique, const Image& reference, int reach);

}  // namespace penumbra
