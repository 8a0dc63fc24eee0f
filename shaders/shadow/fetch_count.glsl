// The texel reads of a lookup, counted in the lighting pass's variant
// that `penumbra bench` renders (SHADOW_COUNT_FETCHES 1,
// LightingPass::count_fetches): each texelFetch, textureGather or
// hardware-compared texture() is one read, whatever the texels it
// returns. Elsewhere SHADOW_FETCHED() is nothing.
#pragma once

#if defined(SHADOW_COUNT_FETCHES) && SHADOW_COUNT_FETCHES
uint shadow_fetches = 0u;
#define SHADOW_FETCHED(n) shadow_fetches += uint(n)
#else
#define SHADOW_FETCHED(n)
#endif
