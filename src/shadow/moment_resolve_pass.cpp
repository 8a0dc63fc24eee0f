#include "shadow/moment_resolve_pass.hpp"

#include <string>

#include "shadow/representation.hpp"
#include "shared/bindings.h"

namespace penumbra {

namespace {
GLuint groups(int size, int local) {
  return static_cast<GLuint>((size + local - 1) / local);
}
}  // namespace

void MomentResolvePass::execute(int light, const gl::Texture& depth_map,
                                const ShadowSettings& settings) {
  const Technique technique = settings.technique;
  const GLenum format = representation_format(technique);
  const auto key = std::make_pair(technique, uses_quantized_moments(settings));
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"REPRESENTATION", std::to_string(technique_define(technique))},
                           {"MSM_QUANTIZED", key.second ? "1" : "0"},
                           {"IMAGE_FORMAT", image_format_qualifier(format)}};
    it = programs_.emplace(key, gl::Program::compute("filter/resolve.comp", defines)).first;
  }
  const std::size_t index = static_cast<std::size_t>(light);
  if (maps_.size() <= index) maps_.resize(index + 1);
  gl::Texture& map = maps_[index];
  if (!map || map.width() != depth_map.width() || map.format() != format) {
    map = gl::Texture(gl::TextureInfo{.format = format,
                                      .width = depth_map.width(),
                                      .height = depth_map.height(),
                                      .label = "shadow representation"});
  }

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "resolve");
  it->second.use();
  glProgramUniform1f(it->second.id(), 0, settings.esm_c);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, depth_map.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, map.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glDispatchCompute(groups(map.width(), 16), groups(map.height(), 16), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
