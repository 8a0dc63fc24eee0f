// The PCF/PCSS sample set: kPoissonSampleCount points in [-1, 1]^2, every
// prefix well spread (src/shadow/poisson_disc.cpp), the first one the centre.
// Bound where penumbra's renderer binds it, or in the lookup an engine
// includes where the engine chose (ShadowBindings::poisson_buffer).
#ifndef PENUMBRA_POISSON_BINDING
#define PENUMBRA_POISSON_BINDING BINDING_POISSON_SSBO
#endif
layout(std430, binding = PENUMBRA_POISSON_BINDING) readonly buffer PoissonSamples {
  vec2 poisson_samples[];
};

// Sample i rotated by the angle whose cosine and sine are `rotation`.
vec2 rotated_poisson(int i, vec2 rotation) {
  vec2 p = poisson_samples[i];
  return vec2(p.x * rotation.x - p.y * rotation.y, p.x * rotation.y + p.y * rotation.x);
}
