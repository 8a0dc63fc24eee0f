// What a filterable technique stores per texel, split in the three steps a
// filter needs, so the resolve (filter/resolve.comp) and the fused resolve +
// Gaussian (filter/fused_filter.comp) write the same values from one
// definition:
//   stage(z)   the per-texel value the expansion is made from: z-bar itself,
//              or the exponential of ESM and EVSM2; a fused filter keeps it
//              in shared memory, 4 bytes a texel instead of the
//              representation's 16
//   expand(s)  the values a filter averages, linearly: (z, z^2) for VSM
//              (Donnelly & Lauritzen 2006), exp(c (z - 1)) for ESM (Annen et
//              al. 2008), the moments of u = 2 z - 1 for MSM (Peters & Klein
//              2015, eq. 1), the warps' first two moments for EVSM (evsm.glsl)
//   store(m)   the stored form of averaged values: msm16's optimized
//              quantization (an affine map, so it commutes with any
//              normalized filter: quantize-then-blur and blur-then-quantize
//              differ by rounding only), the identity otherwise
// Defines: REPRESENTATION (the TECHNIQUE_* of a filterable technique) and
// MSM_QUANTIZED (0/1).
#pragma once
#include "../shared/bindings.h"
#include "esm.glsl"
#include "evsm.glsl"
#include "msm.glsl"

#if REPRESENTATION == TECHNIQUE_VSM || REPRESENTATION == TECHNIQUE_EVSM2
#define REPRESENTATION_TYPE vec2
#elif REPRESENTATION == TECHNIQUE_ESM
#define REPRESENTATION_TYPE float
#else
#define REPRESENTATION_TYPE vec4
#endif
// EVSM4_STAGE_WARPS (fused filter, where shared memory allows): evsm4
// stages both warps, so each texel's two exponentials are taken once, not
// once for every tap that reads it.
#ifndef EVSM4_STAGE_WARPS
#define EVSM4_STAGE_WARPS 0
#endif
#if REPRESENTATION == TECHNIQUE_EVSM4 && EVSM4_STAGE_WARPS
#define STAGE_TYPE vec2
#else
#define STAGE_TYPE float
#endif

// The constants of the exponential representations (ShadowSettings).
struct RepresentationConstants {
  float esm_c;
  float evsm_positive;
  float evsm_negative;
};

STAGE_TYPE representation_stage(float z, RepresentationConstants k) {
#if REPRESENTATION == TECHNIQUE_ESM
  return esm_encode(z, k.esm_c);
#elif REPRESENTATION == TECHNIQUE_EVSM2
  return evsm_warp(z, k.evsm_positive, k.evsm_negative).x;
#elif REPRESENTATION == TECHNIQUE_EVSM4 && EVSM4_STAGE_WARPS
  return evsm_warp(z, k.evsm_positive, k.evsm_negative);
#else
  return z;  // evsm4 too where its two warps do not fit (a fused filter at large W)
#endif
}

REPRESENTATION_TYPE representation_expand(STAGE_TYPE s, RepresentationConstants k) {
#if REPRESENTATION == TECHNIQUE_VSM || REPRESENTATION == TECHNIQUE_EVSM2
  return vec2(s, s * s);  // the first two moments (of z, or of its warp)
#elif REPRESENTATION == TECHNIQUE_EVSM4
#if EVSM4_STAGE_WARPS
  vec2 w = s;
#else
  vec2 w = evsm_warp(s, k.evsm_positive, k.evsm_negative);
#endif
  return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
#elif REPRESENTATION == TECHNIQUE_ESM
  return s;
#else
  return msm_moments(s);  // the moments of u = 2 z - 1 (see msm.glsl)
#endif
}

// The texel written to the map (its image format keeps the channels it has).
vec4 representation_store(REPRESENTATION_TYPE m) {
#if REPRESENTATION == TECHNIQUE_VSM || REPRESENTATION == TECHNIQUE_EVSM2
  return vec4(m, 0.0, 0.0);
#elif REPRESENTATION == TECHNIQUE_ESM
  return vec4(m, 0.0, 0.0, 0.0);
#elif MSM_QUANTIZED
  return msm_quantize(m);
#else
  return m;
#endif
}
