#pragma once
// Screen-space ambient occlusion over the G-buffer (seed 003, Task 6): the
// raw AO with a per-pixel rotated kernel (shaders/render/ssao.comp), a
// separable depth- and normal-aware blur (ssao_blur.comp), and at half
// resolution a joint bilateral upsampling (ssao_upsample.comp).
#include <glm/glm.hpp>
#include <vector>

#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "render/gbuffer_pass.hpp"

namespace penumbra {

class SsaoPass {
 public:
  SsaoPass();

  // Computes the AO of the G-buffer drawn with the camera matrices `view`
  // and `projection`. Textures are reallocated only when a size changes;
  // programs are compiled on first use.
  void execute(const GBufferPass& gbuffer, const glm::mat4& view, const glm::mat4& projection,
               const SsaoSettings& settings);

  // R32F at the G-buffer's size: 1 = unoccluded, and 1 where no geometry
  // was drawn. Valid after execute().
  [[nodiscard]] const gl::Texture& output() const { return *output_; }

 private:
  void dispatch(const gl::Program& program, const gl::Texture& input, const gl::Texture& target);

  gl::Program ao_program_, blur_programs_[2], upsample_program_;
  gl::Buffer parameters_;
  std::vector<glm::vec4> kernel_;
  gl::Texture raw_, intermediate_, blurred_, upsampled_;
  const gl::Texture* output_ = nullptr;
};

}  // namespace penumbra
