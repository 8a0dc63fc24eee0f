// Exponential shadow maps (Annen, Mertens, Seidel, Flerackers, Kautz,
// "Exponential Shadow Maps", GI 2008). The map stores exp(c * z) of the
// occluder depth z; after filtering, the shadow test
//   s = min(1, E[exp(c * z)] * exp(-c * z_f))
// is exp(-c * (z_f - z)) for a single occluder: 1 when the receiver is at
// or in front of it, falling off exponentially behind it.
//
// Shifted encoding: exp(c * z) overflows float32 past c * z ~ 88.7, and a
// large c is what makes ESM sharp. We store exp(c * (z - 1)) instead,
// which lies in [exp(-c), 1] for z in [0, 1]. The factor exp(-c) is common
// to every texel, survives any normalized (sum-to-1) filter unchanged and
// cancels in the ratio: filtered * exp(-c * (z_f - 1)) equals the paper's
// E[exp(c z)] * exp(-c z_f). The smallest stored value, exp(-c), must stay
// a normal float (>= 2^-126 = exp(-87.34)), which bounds c at 87.
//
// The seed states the unshifted form, min(1, filtered * exp(-c * z_f)).
#pragma once

// Value written to the map for relative occluder depth z in [0, 1].
float esm_encode(float z, float c) { return exp(c * (z - 1.0)); }

// Lit fraction (1 = lit) for a filtered esm_encode() value and the
// receiver's relative depth. Evaluated in log space so that no product can
// overflow. A filtered value below exp(-c) (a flushed denormal, a
// summed-area-table difference that cancelled to 0 or below) is read as an
// occluder at depth 0, the nearest a valid map can hold; the receiver is
// then lit only at depth 0 and shadowed behind it. No Inf/NaN for any
// filtered value and c in [1, 87].
float shadow_esm(float filtered, float receiver_depth, float c) {
  float log_occluder = filtered > 0.0 ? max(log(filtered), -c) : -c;
  return exp(min(log_occluder - c * (receiver_depth - 1.0), 0.0));
}
