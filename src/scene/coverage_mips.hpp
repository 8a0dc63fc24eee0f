#pragma once
// The mip chain of an alpha-tested texture, built so that every level keeps
// level 0's coverage: box-filtered alpha drifts towards the mean and, for
// sparse foliage, under the cutoff, so leaves thin out with distance and in
// small shadow maps. At each level, as many texels as keep level 0's
// fraction at or above the cutoff pass, those of largest averaged alpha
// (Castaño, "Computing Alpha Mipmaps", 2010, which scales the level's
// alpha so that the same texels pass).
#include <cstdint>
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

struct MipLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // as TextureImage: sRGB colour, linear alpha
};

// The fraction of a level's texels whose alpha (byte / 255) is at or
// above `cutoff`.
double alpha_coverage(const MipLevel& level, float cutoff);

// Levels 0 (the image) to 1 x 1, sized as OpenGL sizes them (each side
// halved, rounded down, at least 1). Colour is averaged in linear light
// (as OpenGL filters sRGB textures, section 8.24), alpha linearly; with
// `cutoff` in (0, 1], each level's alpha is then moved the least it takes
// (raised to the cutoff, or lowered just under it) for its coverage at the
// cutoff to be level 0's, to the nearest texel. Otherwise the alpha is the
// plain box-filtered mean.
std::vector<MipLevel> coverage_mip_chain(const TextureImage& image, float cutoff);

// The cutoff that a material's texture alpha is tested against (the
// material's cutoff divided by its alpha factor), or a negative number when
// the texture's alpha is not tested (an opaque material, or one whose
// factor makes every texel a hole).
float texture_alpha_cutoff(const Material& m);

}  // namespace penumbra
