#include "penumbra/shadow/moment_resolve_pass.hpp"

#include <string>

#include "penumbra/filter/layer_runs.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

TexelTraffic MomentResolvePass::texel_traffic(GLenum depth_format, Technique technique,
                                              int samples) {
  return {static_cast<double>(samples * bytes_per_texel(depth_format)),
          static_cast<double>(bytes_per_texel(representation_format(technique)))};
}

void MomentResolvePass::execute(const gl::Texture& depth_maps, const ShadowMapSettings& settings,
                                std::span<const std::uint8_t> layers) {
  const Technique technique = settings.technique;
  const GLenum format = representation_format(technique);
  const int samples = depth_maps.samples();
  const auto key = std::make_tuple(technique, uses_quantized_moments(settings), samples);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"REPRESENTATION", std::to_string(technique_define(technique))},
                           {"MSM_QUANTIZED", std::get<1>(key) ? "1" : "0"},
                           {"IMAGE_FORMAT", image_format_qualifier(format)},
                           {"SAMPLES", std::to_string(samples)}};
    it = programs_.emplace(key, gl::Program::compute("filter/resolve.comp", defines)).first;
  }
  // Unfiltered (--blur 0), the representation is the map the lighting
  // reads, and carries the mip chain when there is one.
  const int levels = filter_define(settings) == FILTER_NONE
                         ? filtered_map_levels(settings, depth_maps.width(), depth_maps.height())
                         : 1;
  const bool all = gl::ensure_texture_array(maps_, format, depth_maps.width(), depth_maps.height(),
                                            depth_maps.layers(), "shadow representations", levels);

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "resolve");
  it->second.use();
  set_representation_constants(it->second.id(), settings);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, depth_maps.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, maps_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
  for_each_layer_run(layers, maps_.layers(), all, [&](int first, int count) {
    glProgramUniform1i(it->second.id(), 3, first);
    glDispatchCompute(gl::work_groups(maps_.width(), 16), gl::work_groups(maps_.height(), 16),
                      static_cast<GLuint>(count));
  });
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
