#include "render/ssao_pass.hpp"

#include <algorithm>

#include "penumbra/shared/bindings.h"
#include "penumbra/shared/gpu_types.h"
#include "render/ssao_kernel.hpp"

namespace penumbra {

static_assert(sizeof(gpu::GpuSsao) == 3 * 64 + SSAO_MAX_SAMPLES * 16 + 3 * 16,
              "GpuSsao must match std140");
static_assert(kMaxSsaoSamples == SSAO_MAX_SAMPLES);

namespace {

constexpr int kLocalSize = 8;  // local_size_x and local_size_y of the SSAO shaders

void ensure(gl::Texture& texture, int width, int height, const char* label) {
  if (!texture || texture.width() != width || texture.height() != height) {
    texture = gl::Texture(
        gl::TextureInfo{.format = GL_R32F, .width = width, .height = height, .label = label});
  }
}

}  // namespace

SsaoPass::SsaoPass() : parameters_(sizeof(gpu::GpuSsao), nullptr, true, "ssao block") {}

void SsaoPass::dispatch(const gl::Program& program, const gl::Texture& input,
                        const gl::Texture& target) {
  program.use();
  glBindTextureUnit(UNIT_AMBIENT_OCCLUSION, input.id());
  glBindSampler(UNIT_AMBIENT_OCCLUSION, 0);
  glBindImageTexture(IMAGE_OUTPUT, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(gl::work_groups(target.width(), kLocalSize),
                    gl::work_groups(target.height(), kLocalSize), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void SsaoPass::execute(const GBufferPass& gbuffer, const glm::mat4& view,
                       const glm::mat4& projection, const SsaoSettings& settings) {
  if (!ao_program_) {
    ao_program_ = gl::Program::compute("render/ssao.comp");
    blur_programs_[0] = gl::Program::compute("render/ssao_blur.comp", {{"AXIS", "0"}});
    blur_programs_[1] = gl::Program::compute("render/ssao_blur.comp", {{"AXIS", "1"}});
    upsample_program_ = gl::Program::compute("render/ssao_upsample.comp");
  }
  if (static_cast<int>(kernel_.size()) != settings.samples) kernel_ = ssao_kernel(settings.samples);

  const int width = gbuffer.depth().width(), height = gbuffer.depth().height();
  const int scale = settings.half_resolution ? 2 : 1;
  const int ao_width = (width + scale - 1) / scale, ao_height = (height + scale - 1) / scale;

  gpu::GpuSsao block{};
  block.view = view;
  block.projection = projection;
  block.inverse_projection = glm::mat4(glm::inverse(glm::dmat4(projection)));
  std::copy(kernel_.begin(), kernel_.end(), block.kernel);
  block.size = glm::ivec4(ao_width, ao_height, width, height);
  block.radius = settings.radius;
  block.bias = settings.bias;
  block.range = settings.range;
  block.sample_count = settings.samples;
  block.blur_radius = settings.blur;
  block.scale = scale;
  parameters_.update(&block, sizeof block);

  ensure(raw_, ao_width, ao_height, "ssao raw");
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "ssao");
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_SSAO_UBO, parameters_.id());
  glBindTextureUnit(UNIT_GBUFFER_DEPTH, gbuffer.depth().id());
  glBindTextureUnit(UNIT_GBUFFER_NORMAL, gbuffer.normal().id());
  glBindSampler(UNIT_GBUFFER_DEPTH, 0);
  glBindSampler(UNIT_GBUFFER_NORMAL, 0);

  ao_program_.use();
  glBindImageTexture(IMAGE_OUTPUT, raw_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glDispatchCompute(gl::work_groups(ao_width, kLocalSize), gl::work_groups(ao_height, kLocalSize),
                    1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  output_ = &raw_;

  if (settings.blur > 0) {
    ensure(intermediate_, ao_width, ao_height, "ssao blur intermediate");
    ensure(blurred_, ao_width, ao_height, "ssao blurred");
    dispatch(blur_programs_[0], raw_, intermediate_);
    dispatch(blur_programs_[1], intermediate_, blurred_);
    output_ = &blurred_;
  }
  if (scale > 1) {
    ensure(upsampled_, width, height, "ssao upsampled");
    dispatch(upsample_program_, *output_, upsampled_);
    output_ = &upsampled_;
  }
  glPopDebugGroup();
}

}  // namespace penumbra
