#pragma once
// Error of a shadow-factor image (1 = lit) against a reference, over the
// pixels that see geometry (alpha = 1 in both).
#include "io/image.hpp"

namespace penumbra {

struct ShadowMetrics {
  long pixels = 0;  // geometry pixels compared
  double mean_absolute_error = 0.0;
  double rmse = 0.0;
  double max_error = 0.0;
  // Light leaking: reference < 0.1 (in shadow) while the technique > 0.3.
  double leak_fraction = 0.0;
  // Over-darkening: reference > 0.9 (lit) while the technique < 0.7.
  double over_dark_fraction = 0.0;
};

inline constexpr float kLeakReferenceBelow = 0.1f;
inline constexpr float kLeakTechniqueAbove = 0.3f;
inline constexpr float kOverDarkReferenceAbove = 0.9f;
inline constexpr float kOverDarkTechniqueBelow = 0.7f;

// Compares the red channels. Throws RuntimeError if the sizes differ.
ShadowMetrics compare_shadow(const Image& technique, const Image& reference);

}  // namespace penumbra
