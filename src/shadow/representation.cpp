#include "penumbra/shadow/representation.hpp"

#include <algorithm>

#include "penumbra/error.hpp"
#include "penumbra/filter/fused_filter_pass.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

int technique_define(Technique technique) {
  switch (technique) {
    case Technique::None:
      return TECHNIQUE_NONE;
    case Technique::Hard:
      return TECHNIQUE_HARD;
    case Technique::Pcf:
      return TECHNIQUE_PCF;
    case Technique::Pcss:
      return TECHNIQUE_PCSS;
    case Technique::Backprojection:
      return TECHNIQUE_BACKPROJECTION;
    case Technique::Vsm:
      return TECHNIQUE_VSM;
    case Technique::Esm:
      return TECHNIQUE_ESM;
    case Technique::Msm:
      return TECHNIQUE_MSM;
    case Technique::Msm16:
      return TECHNIQUE_MSM16;
    case Technique::Evsm2:
      return TECHNIQUE_EVSM2;
    case Technique::Evsm4:
      return TECHNIQUE_EVSM4;
  }
  return TECHNIQUE_NONE;
}

int filter_define(const ShadowMapSettings& settings) {
  if (!is_filterable(settings.technique) || settings.blur == 0) return FILTER_NONE;
  return settings.filter == Filter::Sat ? FILTER_SAT : FILTER_GAUSSIAN;
}

int depth_samples(const ShadowMapSettings& settings) {
  return is_filterable(settings.technique) ? settings.shadow_msaa : 1;
}

bool draws_second_surfaces(const ShadowMapSettings& settings) {
  return settings.technique == Technique::Backprojection;
}

int max_fused_blur(const ShadowMapSettings& settings) {
  if (depth_samples(settings) <= 1) return kMaxFusedBlur;
  // The widest radius whose tile, staging the representation's channels,
  // fits the 32 KiB of shared memory every GL 4.5 device has, so the plan
  // is the same on every device.
  constexpr int kMinSharedBytes = 32768;
  const GLenum format = representation_format(settings.technique);
  int radius = kMaxFusedBlur;
  while (radius > 0 && FusedFilterPass::tile_rows(radius, channel_count(format), kMinSharedBytes,
                                                  FusedFilterPass::staged_channels(
                                                      format, depth_samples(settings))) == 0) {
    --radius;
  }
  return radius;
}

bool uses_fused_filter(const ShadowMapSettings& settings) {
  return settings.fused && filter_define(settings) == FILTER_GAUSSIAN &&
         settings.blur <= max_fused_blur(settings);
}

bool uses_shadow_mips(const ShadowMapSettings& settings) {
  return settings.shadow_mips && is_filterable(settings.technique) &&
         filter_define(settings) != FILTER_SAT;
}

int filtered_map_levels(const ShadowMapSettings& settings, int width, int height) {
  if (!uses_shadow_mips(settings)) return 1;
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

bool uses_quantized_moments(const ShadowMapSettings& settings) {
  return settings.technique == Technique::Msm16 ||
         (settings.technique == Technique::Msm && filter_define(settings) == FILTER_SAT);
}

GLenum representation_format(Technique technique) {
  switch (technique) {
    case Technique::Vsm:
      return GL_RG32F;
    case Technique::Esm:
      return GL_R32F;
    case Technique::Msm:
      return GL_RGBA32F;
    case Technique::Msm16:
      return GL_RGBA16;
    case Technique::Evsm2:
      return GL_RG32F;
    case Technique::Evsm4:
      return GL_RGBA32F;
    default:
      throw RuntimeError("technique has no filterable representation");
  }
}

void set_representation_constants(GLuint program, const ShadowMapSettings& settings) {
  glProgramUniform1f(program, 0, settings.esm_c);
  glProgramUniform1f(program, 1, settings.evsm_positive);
  glProgramUniform1f(program, 2, settings.evsm_negative);
}

std::string format_name(GLenum format) {
  if (format == GL_DEPTH_COMPONENT32F) return "DEPTH32F";
  std::string name = image_format_qualifier(format);
  for (char& c : name) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return name;
}

std::string image_format_qualifier(GLenum format) {
  switch (format) {
    case GL_R32F:
      return "r32f";
    case GL_RG32F:
      return "rg32f";
    case GL_RGBA32F:
      return "rgba32f";
    case GL_RGBA16:
      return "rgba16";
    case GL_R32UI:
      return "r32ui";
    case GL_RG32UI:
      return "rg32ui";
    case GL_RGBA32UI:
      return "rgba32ui";
    default:
      throw RuntimeError("no image format qualifier for this texture format");
  }
}

GLenum integer_format_with_channels_of(GLenum format) {
  switch (format) {
    case GL_R32F:
      return GL_R32UI;
    case GL_RG32F:
      return GL_RG32UI;
    default:
      return GL_RGBA32UI;
  }
}

GLenum float_format_with_channels_of(GLenum format) {
  switch (channel_count(format)) {
    case 1:
      return GL_R32F;
    case 2:
      return GL_RG32F;
    default:
      return GL_RGBA32F;
  }
}

int channel_count(GLenum format) {
  switch (format) {
    case GL_R32F:
    case GL_R32UI:
      return 1;
    case GL_RG32F:
    case GL_RG32UI:
      return 2;
    default:
      return 4;
  }
}

int bytes_per_texel(GLenum format) {
  switch (format) {
    case GL_R32F:
    case GL_R32UI:
    case GL_DEPTH_COMPONENT32F:
      return 4;
    case GL_RG32F:
    case GL_RG32UI:
    case GL_RGBA16:
      return 8;
    default:
      return 16;
  }
}

}  // namespace penumbra
