#include "penumbra/filter/mip_chain_pass.hpp"

#include <algorithm>

#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {
constexpr int kDownsampleGroup = 8;  // local_size_x and _y of downsample.comp
}  // namespace

TexelTraffic MipChainPass::texel_traffic(GLenum format, int width, int height, int levels) {
  if (width <= 0 || height <= 0 || levels <= 1) return {};
  double read = 0.0, written = 0.0;
  int w = width, h = height;
  for (int level = 1; level < levels; ++level) {
    const int coarser_w = std::max(w / 2, 1), coarser_h = std::max(h / 2, 1);
    // Each coarser texel reads the 2x2 texels it covers (clamped reads at
    // a 1-texel-wide level read the same texel twice; counted once).
    read += static_cast<double>(std::min(2 * coarser_w, w)) * std::min(2 * coarser_h, h);
    written += static_cast<double>(coarser_w) * coarser_h;
    w = coarser_w;
    h = coarser_h;
  }
  const double base = static_cast<double>(width) * height;
  const double bytes = bytes_per_texel(format);
  return {bytes * read / base, bytes * written / base};
}

void MipChainPass::execute(const gl::Texture& maps) {
  const GLenum format = maps.format();
  auto it = programs_.find(format);
  if (it == programs_.end()) {
    it = programs_
             .emplace(format,
                      gl::Program::compute("filter/downsample.comp",
                                           {{"IMAGE_FORMAT", image_format_qualifier(format)}}))
             .first;
  }
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "mip chain");
  it->second.use();
  int w = maps.width(), h = maps.height();
  for (int level = 1; level < maps.levels(); ++level) {
    w = std::max(w / 2, 1);
    h = std::max(h / 2, 1);
    glBindImageTexture(IMAGE_OUTPUT, maps.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, format);
    glBindImageTexture(IMAGE_OUTPUT_2, maps.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, format);
    glDispatchCompute(gl::work_groups(w, kDownsampleGroup), gl::work_groups(h, kDownsampleGroup),
                      static_cast<GLuint>(maps.layers()));
    // The next level reads what this one wrote.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
