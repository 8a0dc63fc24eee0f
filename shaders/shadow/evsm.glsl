// Exponential variance shadow maps (Lauritzen & McCool, "Layered Variance
// Shadow Maps", GI 2008, sec. 4; Lauritzen, "Summed-Area Variance Shadow
// Maps", GPU Gems 3, ch. 8). The depth is warped by exponentials before its
// first two moments are stored; Chebyshev's bound (vsm.glsl) then holds in
// the warped variable, where a receiver behind a nearer occluder lies
// exponentially farther from the mean, so VSM's light bleeding shrinks.
//   positive warp  p(z) =  exp( c+ u),  u = 2 z - 1 in [-1, 1]
//   negative warp  n(z) = -exp(-c- u)
// Both are increasing in z, so "receiver behind the mean" keeps its sense.
// EVSM2 stores (E[p], E[p^2]); EVSM4 also (E[n], E[n^2]) and takes the
// smaller of the two bounds (the negative warp corrects the positive one's
// bleeding where the receiver is close behind a far occluder). u spans
// [-1, 1] rather than [0, 1] so that p^2 spans exp(-2 c+) .. exp(2 c+):
// in float32 that keeps c+ <= 44 (kEvsmMaxExponent: 42, as Lauritzen's and
// MJP's code clamp it).
#pragma once
#include "vsm.glsl"

// (p, n) of relative depth z: the per-texel values whose moments the map holds.
vec2 evsm_warp(float z, float positive_exponent, float negative_exponent) {
  float u = fma(2.0, z, -1.0);
  return vec2(exp(positive_exponent * u), -exp(-negative_exponent * u));
}

// Chebyshev's bound in one warped variable. min_variance is in z-bar^2
// units (VSM's, per view); the warp scales a small depth spread dz by its
// derivative |w'(z)| = 2 c |w(z)| at the receiver, so the floor becomes
// (2 c w)^2 min_variance there (the warped counterpart of VSM's floor,
// evaluated at the receiver as Filament's and MJP's EVSM do).
//
// The bound is evaluated in units of s = max(|w|, |E[w]|): it does not
// change under scaling the variable by s > 0, and in float32 the raw values
// do not fit it. At c = 42 (2 c w)^2 reaches 7056 e^84 > 3.4e38, and the
// negative warp's moments near z = 1 are of the order e^-84, where VSM's
// guard against 0/0 (a 1e-30 floor on the denominator) would swamp them.
// Where the bound is below 1 (E[w] < w), |x| / s <= e^84 for every texel's
// warp x and E[w^2] / s^2 <= max |x| / s, so every scaled value is finite.
float evsm_bound(vec2 moments, float warped_receiver, float exponent, float min_variance) {
  float inverse = 1.0 / max(abs(warped_receiver), abs(moments.x));
  vec2 scaled = vec2(moments.x * inverse, moments.y * inverse * inverse);
  float slope = 2.0 * exponent * abs(warped_receiver) * inverse;
  return shadow_vsm(scaled, warped_receiver * inverse, slope * slope * min_variance, 0.0);
}

// Lit fraction (1 = lit) of a filtered EVSM2 texel (E[p], E[p^2]).
float shadow_evsm2(vec2 moments, float z, float positive_exponent, float min_variance) {
  float p = evsm_warp(z, positive_exponent, 1.0).x;
  return evsm_bound(moments, p, positive_exponent, min_variance);
}

// Lit fraction of a filtered EVSM4 texel (E[p], E[p^2], E[n], E[n^2]): the
// tighter (smaller) of the two upper bounds.
float shadow_evsm4(vec4 moments, float z, float positive_exponent, float negative_exponent,
                   float min_variance) {
  vec2 w = evsm_warp(z, positive_exponent, negative_exponent);
  return min(evsm_bound(moments.xy, w.x, positive_exponent, min_variance),
             evsm_bound(moments.zw, w.y, negative_exponent, min_variance));
}

// The relative depth whose positive warp is p (for showing the maps).
float evsm_unwarp(float p, float positive_exponent) {
  return 0.5 * log(p) / positive_exponent + 0.5;
}
