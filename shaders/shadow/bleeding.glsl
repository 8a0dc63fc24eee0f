// Light-bleeding reduction for the filterable techniques (VSM, ESM, MSM):
// the upper bounds of VSM and MSM overestimate the lit fraction where
// several occluders overlap, so the lowest `amount` of the lit range is
// cut off and the rest stretched back to [0, 1] (Lauritzen, "Summed-Area
// Variance Shadow Maps", GPU Gems 3, ch. 8: linstep(amount, 1, lit)).
// `lit` is the lit fraction (1 = lit); amount 0 leaves it unchanged.
#pragma once

float reduce_light_bleeding(float lit, float amount) {
  // (lit - amount) / (1 - amount) written as 1 - (1 - lit) / (1 - amount),
  // so that with the max() amount = 1 degenerates to a step at lit = 1.
  return 1.0 - clamp((1.0 - lit) / max(1.0 - amount, 1e-6), 0.0, 1.0);
}
