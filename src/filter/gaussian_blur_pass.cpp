#include "penumbra/filter/gaussian_blur_pass.hpp"

#include <string>

#include "penumbra/filter/gaussian.hpp"
#include "penumbra/filter/layer_runs.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"
#include "shared/filter_tiles.h"

namespace penumbra {

namespace {

// `texture` as a 2D array shaped like `like`, with `levels` mip levels.
bool ensure_like(gl::Texture& texture, const gl::Texture& like, const char* label, int levels = 1) {
  return gl::ensure_texture_array(texture, like.format(), like.width(), like.height(),
                                  like.layers(), label, levels);
}

}  // namespace

GaussianBlurPass::GaussianBlurPass(Staging staging)
    : shared_memory_(stages_in_shared_memory(staging)) {}

const gl::Program& GaussianBlurPass::program(GLenum format, int axis, int radius) {
  auto key = std::make_tuple(format, axis, radius);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"AXIS", std::to_string(axis)},
                           {"RADIUS", std::to_string(radius)},
                           {"GAUSSIAN_WEIGHTS", gaussian_weight_list(radius)},
                           {"STAGE_IN_SHARED_MEMORY", shared_memory_ ? "1" : "0"},
                           {"IMAGE_FORMAT", image_format_qualifier(format)}};
    it = programs_.emplace(key, gl::Program::compute("filter/gaussian_blur.comp", defines)).first;
  }
  return it->second;
}

void GaussianBlurPass::dispatch(const gl::Program& program, const gl::Texture& from,
                                const gl::Texture& to, int axis,
                                std::span<const std::uint8_t> layers, bool all) {
  program.use();
  glBindTextureUnit(UNIT_COMPUTE_INPUT, from.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, to.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, to.format());
  // Without the tile an invocation filters a run of texels along the axis.
  const int along = GAUSSIAN_TILE_ALONG * (shared_memory_ ? 1 : FILTER_DIRECT_RUN);
  for_each_layer_run(layers, from.layers(), all, [&](int first, int count) {
    glProgramUniform1i(program.id(), 0, first);
    if (axis == 0) {
      glDispatchCompute(gl::work_groups(from.width(), along),
                        gl::work_groups(from.height(), GAUSSIAN_TILE_ACROSS),
                        static_cast<GLuint>(count));
    } else {
      glDispatchCompute(gl::work_groups(from.width(), GAUSSIAN_TILE_ACROSS),
                        gl::work_groups(from.height(), along), static_cast<GLuint>(count));
    }
  });
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

TexelTraffic GaussianBlurPass::texel_traffic(GLenum format, int radius, int axis, int width,
                                             int height) {
  const double along = axis == 0 ? width : height, across = axis == 0 ? height : width;
  const double tiles_along = gl::work_groups(static_cast<int>(along), GAUSSIAN_TILE_ALONG);
  const double tiles_across = gl::work_groups(static_cast<int>(across), GAUSSIAN_TILE_ACROSS);
  const double texels_read =
      tiles_along * (GAUSSIAN_TILE_ALONG + 2.0 * radius) * tiles_across * GAUSSIAN_TILE_ACROSS;
  const double bytes = bytes_per_texel(format);
  return {bytes * texels_read / (along * across), bytes};
}

void GaussianBlurPass::execute(const gl::Texture& source, int radius, gl::GpuProfiler* profiler,
                               int levels, std::span<const std::uint8_t> layers) {
  ensure_like(intermediate_, source, "blur intermediate");
  const bool all = ensure_like(output_, source, "blurred shadow maps", levels);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "gaussian blur");
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::FilterHorizontal);
    dispatch(program(source.format(), 0, radius), source, intermediate_, 0, layers, all);
  }
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::FilterVertical);
    dispatch(program(source.format(), 1, radius), intermediate_, output_, 1, layers, all);
  }
  glPopDebugGroup();
}

}  // namespace penumbra
