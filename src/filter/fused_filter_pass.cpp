#include "penumbra/filter/fused_filter_pass.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "penumbra/error.hpp"
#include "penumbra/filter/gaussian.hpp"
#include "penumbra/filter/layer_runs.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {

constexpr int kTileX = 32;  // TILE_X of fused_filter.comp

GLuint groups(int size, int tile) {
  return static_cast<GLuint>((size + tile - 1) / tile);
}

}  // namespace

FusedFilterPass::FusedFilterPass() {
  glGetIntegerv(GL_MAX_COMPUTE_SHARED_MEMORY_SIZE, &shared_bytes_);
}

int FusedFilterPass::tile_rows(int radius, int channels, int shared_bytes, int staged_floats) {
  const int span_x = kTileX + 2 * radius;
  const int stride = span_x + 1 - span_x % 2;  // STAGED_STRIDE
  for (int rows : {32, 16, 8}) {               // multiples of the shader's GROUP_Y rows of threads
    const int span_y = rows + 2 * radius;
    const int bytes = span_y * stride * 4 * staged_floats + span_y * kTileX * 4 * channels;
    if (bytes <= shared_bytes) return rows;
  }
  return 0;
}

int FusedFilterPass::staged_channels(GLenum format, int samples) {
  return samples > 1 ? channel_count(format) : 1;
}

bool FusedFilterPass::stages_evsm4_warps(int radius, int shared_bytes) {
  const int rows = tile_rows(radius, 4, shared_bytes);
  return rows > 0 && tile_rows(radius, 4, shared_bytes, 2) == rows;
}

TexelTraffic FusedFilterPass::texel_traffic(GLenum format, int radius, int width, int height,
                                            int shared_bytes, int samples) {
  const int rows =
      tile_rows(radius, channel_count(format), shared_bytes, staged_channels(format, samples));
  if (rows == 0 || width <= 0 || height <= 0) return {};
  const double tiles = static_cast<double>(groups(width, kTileX)) * groups(height, rows);
  const double texels_read = tiles * (kTileX + 2.0 * radius) * (rows + 2.0 * radius);
  return {4.0 * samples * texels_read / (static_cast<double>(width) * height),
          1.0 * bytes_per_texel(format)};
}

void FusedFilterPass::execute(const gl::Texture& depth_maps, const ShadowMapSettings& settings,
                              std::span<const std::uint8_t> layers) {
  const int radius = settings.blur;
  if (radius < 1 || radius > kMaxFusedBlur) {
    throw RuntimeError("the fused filter takes radii 1.." + std::to_string(kMaxFusedBlur));
  }
  const Technique technique = settings.technique;
  const GLenum format = representation_format(technique);
  const int samples = depth_maps.samples();
  const int rows =
      tile_rows(radius, channel_count(format), shared_bytes_, staged_channels(format, samples));
  if (rows == 0) throw RuntimeError("the fused filter's tile does not fit in shared memory");
  const bool quantized = uses_quantized_moments(settings);
  // Several samples stage the mean of their moments, warps included.
  const bool stage_warps =
      technique == Technique::Evsm4 && samples == 1 && stages_evsm4_warps(radius, shared_bytes_);
  const auto key = std::make_tuple(technique, quantized, radius, rows, samples);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"REPRESENTATION", std::to_string(technique_define(technique))},
                           {"MSM_QUANTIZED", quantized ? "1" : "0"},
                           {"IMAGE_FORMAT", image_format_qualifier(format)},
                           {"RADIUS", std::to_string(radius)},
                           {"TILE_Y", std::to_string(rows)},
                           {"EVSM4_STAGE_WARPS", stage_warps ? "1" : "0"},
                           {"GAUSSIAN_WEIGHTS", gaussian_weight_list(radius)},
                           {"SAMPLES", std::to_string(samples)}};
    it = programs_.emplace(key, gl::Program::compute("filter/fused_filter.comp", defines)).first;
  }
  const bool all = gl::ensure_texture_array(
      output_, format, depth_maps.width(), depth_maps.height(), depth_maps.layers(),
      "fused filtered shadow maps",
      filtered_map_levels(settings, depth_maps.width(), depth_maps.height()));

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "resolve+filter (fused)");
  it->second.use();
  set_representation_constants(it->second.id(), settings);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, depth_maps.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, output_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
  for_each_layer_run(layers, output_.layers(), all, [&](int first, int count) {
    glProgramUniform1i(it->second.id(), 3, first);
    glDispatchCompute(groups(output_.width(), kTileX), groups(output_.height(), rows),
                      static_cast<GLuint>(count));
  });
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
