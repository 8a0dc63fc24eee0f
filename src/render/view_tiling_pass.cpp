#include "render/view_tiling_pass.hpp"

#include <algorithm>
#include <string>

#include "penumbra/error.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {

// The float format that keeps `format`'s channels: a depth map's one, a
// representation's (a point light's six 2048^2 faces of depth take 100 MB
// tiled, not 400).
GLenum tiled_format(GLenum format) {
  switch (format) {
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32F:
      return GL_R32F;
    default:
      return float_format_with_channels_of(format);
  }
}

}  // namespace

const gl::Program& ViewTilingPass::program(GLenum format) {
  auto it = programs_.find(format);
  if (it == programs_.end()) {
    it = programs_
             .emplace(format,
                      gl::Program::compute("render/tile_views.comp",
                                           {{"IMAGE_FORMAT", image_format_qualifier(format)}}))
             .first;
  }
  return it->second;
}

int ViewTilingPass::columns(int count) {
  return std::clamp(count, 1, 3);
}

void ViewTilingPass::execute(const gl::Texture& layers, int first, int count) {
  const int cols = columns(count);
  const int rows = (count + cols - 1) / cols;
  const int width = cols * layers.width(), height = rows * layers.height();
  GLint max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  if (width > max_texture || height > max_texture) {
    throw UsageError("the " + std::to_string(count) + " shadow views tiled make a " +
                     std::to_string(width) + "x" + std::to_string(height) +
                     " image, beyond this GPU's limit of " + std::to_string(max_texture) +
                     "; use a smaller --shadow-map-size");
  }
  const GLenum format = tiled_format(layers.format());
  if (!output_ || output_.width() != width || output_.height() != height ||
      output_.format() != format) {
    output_ = gl::Texture();  // the old one freed before the new one is made
    output_ = gl::Texture(gl::TextureInfo{
        .format = format, .width = width, .height = height, .label = "tiled shadow views"});
  }
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "tile shadow views");
  const gl::Program& tile = program(format);
  tile.use();
  glProgramUniform1i(tile.id(), 0, first);
  glProgramUniform1i(tile.id(), 1, count);
  glProgramUniform1i(tile.id(), 2, cols);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, layers.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, output_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glDispatchCompute(static_cast<GLuint>((width + 15) / 16), static_cast<GLuint>((height + 15) / 16),
                    1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
