// The filterable techniques' tests of filtered map values: one place for
// the lighting pass (its technique a compile-time constant) and the lookup
// an engine includes (the technique read from the block at run time).
#pragma once

#include "vsm.glsl"
#include "esm.glsl"
#include "evsm.glsl"
#include "msm.glsl"

// The lit fraction of a receiver at relative depth z against filtered map
// values m of `technique` (TECHNIQUE_VSM and on), before light-bleeding
// reduction. `quantized`: MSM's moments are in the 16-bit quantization
// basis (msm16, and msm read from the summed-area table). texel_depth: a
// texel's size at the receiver in z-bar units (VSM's minimum variance is
// given in squared texels).
float filtered_lit_fraction_of(int technique, bool quantized, GpuShadow params, vec4 m, float z,
                               float texel_depth) {
  float min_variance = params.vsm_min_variance * texel_depth * texel_depth;
  if (technique == TECHNIQUE_VSM) return shadow_vsm(m.xy, z, min_variance, 0.0);
  if (technique == TECHNIQUE_ESM) return shadow_esm(m.x, z, params.esm_c);
  if (technique == TECHNIQUE_EVSM2) {
    return shadow_evsm2(m.xy, z, params.evsm_positive, min_variance);
  }
  if (technique == TECHNIQUE_EVSM4) {
    return shadow_evsm4(m, z, params.evsm_positive, params.evsm_negative, min_variance);
  }
  if (quantized) return 1.0 - msm_intensity16(msm_dequantize(m), z, params.msm_alpha);
  return 1.0 - msm_intensity32(m, z, params.msm_alpha);
}

// The mean occluder depth E[z] of filtered map values (MSM stores the
// moments of u = 2 z - 1: E[z] = (E[u] + 1) / 2).
float filtered_mean_depth_of(int technique, bool quantized, GpuShadow params, vec4 m) {
  if (technique == TECHNIQUE_ESM) return log(max(m.x, 1e-37)) / params.esm_c + 1.0;
  if (technique == TECHNIQUE_VSM) return m.x;
  if (technique == TECHNIQUE_EVSM2 || technique == TECHNIQUE_EVSM4) {
    return evsm_unwarp(max(m.x, 1e-37), params.evsm_positive);
  }
  if (quantized) return msm_unit_depth(msm_dequantize(m).x);
  return msm_unit_depth(m.x);
}
