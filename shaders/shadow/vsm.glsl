// Variance shadow maps (Donnelly & Lauritzen, "Variance Shadow Maps",
// I3D 2006). The filtered map holds the first two moments (E[z], E[z^2])
// of the occluder depth; Chebyshev's one-tailed inequality bounds the
// fraction of occluders at or behind the receiver depth t > mu:
//   P(z >= t) <= p_max(t) = sigma^2 / (sigma^2 + (t - mu)^2),
// which is used as the lit fraction. Returns 1 = lit, 0 = shadowed.
#pragma once
#include "bleeding.glsl"

// min_variance clamps sigma^2 from below: it hides the float cancellation
// in M2 - M1^2 and the acne of a single flat occluder (sigma^2 = 0).
// bleed_reduction is reduce_light_bleeding()'s amount (0 = off).
float shadow_vsm(vec2 moments, float receiver_depth, float min_variance, float bleed_reduction) {
  float mean = moments.x;
  if (receiver_depth <= mean) return 1.0;  // the inequality only holds for t > mu
  // fma: M2 - M1^2 rounded once, which matters where the variance is small.
  float variance = max(fma(-mean, mean, moments.y), min_variance);
  float d = receiver_depth - mean;
  // The max() only matters for min_variance = 0 with d^2 underflowing.
  float p_max = variance / max(variance + d * d, 1e-30);
  return reduce_light_bleeding(p_max, bleed_reduction);
}
