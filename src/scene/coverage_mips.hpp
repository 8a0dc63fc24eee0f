#pragma once
// The mip chain of an alpha-tested texture, built so that every level keeps
// level 0's coverage: box-filtered alpha drifts towards the mean and, for
// sparse foliage, under the cutoff, so leaves thin out with distance and in
// small shadow maps. Each level's alpha is remapped so that the fraction of
// it at or above the cutoff, as a bilinear filter reads it, is level 0's
// (Castaño, "Computing Alpha Mipmaps", 2010).
#include <cstdint>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

struct MipLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // as TextureImage: sRGB colour, linear alpha
};

// The fraction of a level at or above `cutoff` (alpha byte / 255) where a
// bilinear filter reads it (texels repeating at the edges), from 4 x 4
// points a texel (of a subset of the texels, for levels over 65,536).
double alpha_coverage(const MipLevel& level, float cutoff);

// Levels 0 (the image) to 1 x 1, sized as OpenGL sizes them (each side
// halved, rounded down, at least 1). Colour is averaged in linear light
// (as OpenGL filters sRGB textures, section 8.24), alpha linearly; with
// `cutoff` in (0, 1), each level's alpha is then remapped, piecewise
// linearly with 0 and 1 kept, so that its alpha_coverage at the cutoff is
// level 0's. Otherwise the alpha is the plain box-filtered mean.
std::vector<MipLevel> coverage_mip_chain(const TextureImage& image, float cutoff);

// The cutoff that a material's texture alpha is tested against (the
// material's cutoff divided by its alpha factor), or a negative number when
// the texture's alpha is not tested (an opaque material, or one whose
// factor makes every texel a hole).
float texture_alpha_cutoff(const Material& m);

}  // namespace penumbra
