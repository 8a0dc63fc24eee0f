#include "penumbra/filter/texture_copy_pass.hpp"

#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {
// Depth maps are copied into R32F, the same bytes per texel.
GLenum copy_format(GLenum source_format) {
  return source_format == GL_DEPTH_COMPONENT32F ? GL_R32F : source_format;
}
}  // namespace

TexelTraffic TextureCopyPass::texel_traffic(GLenum source_format) {
  return {static_cast<double>(bytes_per_texel(source_format)),
          static_cast<double>(bytes_per_texel(copy_format(source_format)))};
}

void TextureCopyPass::execute(const gl::Texture& source) {
  const GLenum format = copy_format(source.format());
  auto it = programs_.find(format);
  if (it == programs_.end()) {
    it = programs_
             .emplace(format,
                      gl::Program::compute("filter/copy.comp",
                                           {{"IMAGE_FORMAT", image_format_qualifier(format)}}))
             .first;
  }
  gl::ensure_texture_array(output_, format, source.width(), source.height(), source.layers(),
                           "copy");
  it->second.use();
  glBindTextureUnit(UNIT_COMPUTE_INPUT, source.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, output_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
  glDispatchCompute(static_cast<GLuint>((source.width() + 15) / 16),
                    static_cast<GLuint>((source.height() + 15) / 16),
                    static_cast<GLuint>(source.layers()));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace penumbra
