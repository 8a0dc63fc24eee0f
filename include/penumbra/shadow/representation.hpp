#pragma once
// What each filterable technique stores per shadow-map texel, and in which
// texture format.
#include <epoxy/gl.h>

#include <string>

#include "penumbra/settings.hpp"

namespace penumbra {

// The value of the SHADOW_TECHNIQUE define (TECHNIQUE_*) for a technique.
int technique_define(Technique technique);

// The value of the SHADOW_FILTER define (FILTER_*) for the shadow settings.
int filter_define(const ShadowMapSettings& settings);

// Samples per texel of the depth maps the casters are drawn into:
// --shadow-msaa for the filterable techniques, whose resolve averages the
// samples' moments; 1 for those that read depth (hard, pcf, pcss,
// backprojection): a binary test reads one depth per texel, and the one
// samples can give it (the nearest, what --soft's blocker search reads)
// measured worse against the traced reference than the texel centre's
// (docs/rendering.md), so their maps are drawn as at 1.
int depth_samples(const ShadowMapSettings& settings);

// Whether the maps hold each view's second surfaces as well (the nearest
// facing the light behind the first ones, ShadowMapPass::execute()):
// backprojection, whose patches would otherwise miss a caster that another
// hides from the source's centre (the default scene's sphere under its
// slab) but that receivers see through the source's edges.
bool draws_second_surfaces(const ShadowMapSettings& settings);

// The widest radius the fused resolve + Gaussian takes: kMaxFusedBlur, or
// with --shadow-msaa above 1, where each staged texel holds the mean of its
// samples' moments, the widest whose tile still fits 32 KiB of shared
// memory (8 for msm, msm16 and evsm4; 16 for the others).
int max_fused_blur(const ShadowMapSettings& settings);

// Whether the renderer filters with the fused resolve + Gaussian pass
// (FusedFilterPass): --fused on, the Gaussian filter, radius
// 1..max_fused_blur(). Otherwise a filterable technique runs the resolve,
// then the two blur passes or the summed-area table.
bool uses_fused_filter(const ShadowMapSettings& settings);

// Whether the filtered maps carry a mip chain (--shadow-mips) that the
// lighting pass reads trilinearly: a filterable technique filtered by the
// Gaussian (fused or not) or not at all. The summed-area table is a
// table of sums, which no mip of it would average.
bool uses_shadow_mips(const ShadowMapSettings& settings);

// Mip levels of a width x height filtered map: the full chain down to 1x1
// with uses_shadow_mips(), else 1.
int filtered_map_levels(const ShadowMapSettings& settings, int width, int height);

// Whether the map holds the moments in the optimized quantization basis of
// Peters & Klein 2015 (msm_quantize): always for msm16, and for msm summed
// in the fixed-point summed-area table, where the basis spreads the
// moments over [0, 1] and so keeps more of their bits.
bool uses_quantized_moments(const ShadowMapSettings& settings);

// Sized internal format of the technique's map: vsm RG32F (z, z^2),
// esm R32F exp(c (z - 1)), msm RGBA32F (z, z^2, z^3, z^4), msm16 RGBA16
// (the quantized moments), evsm2 RG32F (p, p^2), evsm4 RGBA32F
// (p, p^2, n, n^2) (shaders/shadow/evsm.glsl). Only for filterable
// techniques.
GLenum representation_format(Technique technique);

// Sets the uniforms u_esm_c, u_evsm_positive, u_evsm_negative (locations
// 0-2) of a program that makes representations (representation.glsl's
// RepresentationConstants).
void set_representation_constants(GLuint program, const ShadowMapSettings& settings);

// The name of a sized internal format used here, for reports ("RGBA16").
std::string format_name(GLenum format);

// The GLSL image format qualifier of a sized internal format ("rgba32f").
std::string image_format_qualifier(GLenum format);

// The unsigned-integer format with as many channels (for summed-area
// tables of the representation).
GLenum integer_format_with_channels_of(GLenum format);

// The 32-bit float format with as many channels (a representation's values
// unrounded: the fused filter's rows between its two direct passes, the
// map views' tiles).
GLenum float_format_with_channels_of(GLenum format);

// Channels of a sized colour format used here (1, 2 or 4).
int channel_count(GLenum format);

// Bytes per texel of a sized internal format used here.
int bytes_per_texel(GLenum format);

}  // namespace penumbra
