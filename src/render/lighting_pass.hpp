#pragma once
// Full-screen deferred lighting into a 32-bit float target: the final
// linear colour, or one of the debug views.
#include <map>

#include "core/settings.hpp"
#include "gl/program.hpp"
#include "gl/resources.hpp"
#include "render/gbuffer_pass.hpp"
#include "shadow/shadow_map_pass.hpp"

namespace penumbra {

class LightingPass {
 public:
  LightingPass();

  // The frame, lights and shadow blocks must be bound.
  void execute(const GBufferPass& gbuffer, const ShadowMapPass& shadows, int light_count,
               Technique technique, int width, int height);

  // RGBA32F: rgb as the view defines, alpha 1 where geometry was seen.
  [[nodiscard]] const gl::Texture& output() const { return output_; }

 private:
  const gl::Program& program_for(Technique technique);

  std::map<Technique, gl::Program> programs_;  // one per technique, compiled on first use
  gl::VertexArray empty_vao_;
  gl::Sampler nearest_;
  gl::Texture output_;
  gl::Framebuffer framebuffer_;
  int width_ = 0, height_ = 0;
};

// The value of the SHADOW_TECHNIQUE define for a technique.
int technique_define(Technique technique);

}  // namespace penumbra
