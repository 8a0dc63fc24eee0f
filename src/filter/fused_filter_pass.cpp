#include "penumbra/filter/fused_filter_pass.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "penumbra/error.hpp"
#include "penumbra/filter/gaussian.hpp"
#include "penumbra/filter/layer_runs.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"
#include "shared/filter_tiles.h"

namespace penumbra {

namespace {

constexpr int kTileX = 32;      // TILE_X of fused_filter.comp
constexpr int kDirectRows = 8;  // GROUP_Y: the direct passes' workgroups are 32 x 8 texels
// The direct passes' band of rows: its rows and apron of floats take a few
// MB (2048 wide, msm, W = 16: 9 MB), and the apron adds 2 W / 256 to the
// horizontal pass's work.
constexpr int kDirectBandRows = 256;

}  // namespace

FusedFilterPass::FusedFilterPass(FilterStaging staging)
    : shared_memory_(stages_in_shared_memory(staging)) {
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
  const double tiles =
      static_cast<double>(gl::work_groups(width, kTileX)) * gl::work_groups(height, rows);
  const double texels_read = tiles * (kTileX + 2.0 * radius) * (rows + 2.0 * radius);
  return {4.0 * samples * texels_read / (static_cast<double>(width) * height),
          1.0 * bytes_per_texel(format)};
}

const gl::Program& FusedFilterPass::program(const ProgramKey& key) {
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  const auto [technique, quantized, radius, rows, samples, pass] = key;
  const GLenum format = representation_format(technique);
  // Several samples stage the mean of their moments, warps included; the
  // direct passes stage nothing.
  const bool stage_warps = technique == Technique::Evsm4 && samples == 1 && pass == 0 &&
                           stages_evsm4_warps(radius, shared_bytes_);
  gl::Defines defines = {
      {"REPRESENTATION", std::to_string(technique_define(technique))},
      {"MSM_QUANTIZED", quantized ? "1" : "0"},
      {"IMAGE_FORMAT", image_format_qualifier(format)},
      {"RADIUS", std::to_string(radius)},
      {"TILE_Y", std::to_string(rows)},
      {"EVSM4_STAGE_WARPS", stage_warps ? "1" : "0"},
      {"GAUSSIAN_WEIGHTS", gaussian_weight_list(radius)},
      {"SAMPLES", std::to_string(samples)},
      {"STAGE_IN_SHARED_MEMORY", pass == 0 ? "1" : "0"},
      {"PASS", std::to_string(pass)},
      {"ROWS_FORMAT", image_format_qualifier(float_format_with_channels_of(format))}};
  return programs_.emplace(key, gl::Program::compute("filter/fused_filter.comp", defines))
      .first->second;
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
  const bool quantized = uses_quantized_moments(settings);
  const int rows = shared_memory_ ? tile_rows(radius, channel_count(format), shared_bytes_,
                                              staged_channels(format, samples))
                                  : kDirectRows;
  if (rows == 0) throw RuntimeError("the fused filter's tile does not fit in shared memory");
  const bool all = gl::ensure_texture_array(
      output_, format, depth_maps.width(), depth_maps.height(), depth_maps.layers(),
      "fused filtered shadow maps",
      filtered_map_levels(settings, depth_maps.width(), depth_maps.height()));

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "resolve+filter (fused)");
  const GLuint groups_x = gl::work_groups(output_.width(), kTileX);
  if (shared_memory_) {
    const GLuint groups_y = gl::work_groups(output_.height(), rows);
    const gl::Program& tiled = program({technique, quantized, radius, rows, samples, 0});
    tiled.use();
    set_representation_constants(tiled.id(), settings);
    glBindTextureUnit(UNIT_COMPUTE_INPUT, depth_maps.id());
    glBindSampler(UNIT_COMPUTE_INPUT, 0);
    glBindImageTexture(IMAGE_OUTPUT, output_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
    for_each_layer_run(layers, output_.layers(), all, [&](int first, int count) {
      glProgramUniform1i(tiled.id(), 3, first);
      glDispatchCompute(groups_x, groups_y, static_cast<GLuint>(count));
    });
  } else {
    // A band of a layer at a time through the rows: a band's floats and
    // its apron, not the array's (a point light's six 2048^2 faces of msm
    // would take 400 MB, one of them 64).
    const gl::Program& horizontal = program({technique, quantized, radius, rows, samples, 1});
    const gl::Program& vertical = program({technique, quantized, radius, rows, samples, 2});
    const GLenum between = float_format_with_channels_of(format);
    const int height = depth_maps.height();
    const int band = std::min(kDirectBandRows, height);
    gl::ensure_texture_array(rows_, between, depth_maps.width(),
                             std::min(band + 2 * radius, height), 1, "fused filter rows");
    set_representation_constants(horizontal.id(), settings);
    glBindSampler(UNIT_COMPUTE_INPUT, 0);
    // One step over texel rows [from, to) of `layer` (uniform u_rows: those
    // rows, and the band's first row that the rows' texture starts at).
    const auto step = [&](const gl::Program& program, const gl::Texture& input,
                          const gl::Texture& target, GLenum target_format, int layer, int from,
                          int to, int band_first) {
      program.use();
      glBindTextureUnit(UNIT_COMPUTE_INPUT, input.id());
      glBindImageTexture(IMAGE_OUTPUT, target.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, target_format);
      glProgramUniform1i(program.id(), 3, layer);
      glProgramUniform3i(program.id(), 4, from, to, band_first);
      const bool along_rows = &program == &horizontal;
      glDispatchCompute(
          gl::work_groups(output_.width(), kTileX * (along_rows ? FILTER_DIRECT_RUN : 1)),
          gl::work_groups(to - from, kDirectRows * (along_rows ? 1 : FILTER_DIRECT_RUN)), 1);
    };
    for_each_layer_run(layers, output_.layers(), all, [&](int first, int count) {
      for (int layer = first; layer < first + count; ++layer) {
        for (int b0 = 0; b0 < height; b0 += band) {
          const int b1 = std::min(b0 + band, height);
          const int r0 = std::max(b0 - radius, 0), r1 = std::min(b1 + radius, height);
          step(horizontal, depth_maps, rows_, between, layer, r0, r1, r0);
          glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
          step(vertical, rows_, output_, format, layer, b0, b1, r0);
          // The next band's rows overwrite what this one read.
          glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        }
      }
    });
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
