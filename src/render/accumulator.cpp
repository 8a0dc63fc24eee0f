#include "render/accumulator.hpp"

#include <stdexcept>
#include <string_view>
#include <vector>

#include "penumbra/shared/bindings.h"

namespace penumbra {
namespace {

// Makes `texture` an RGBA32F 2D texture of this size, reallocating only
// when the size changes.
void ensure_rgba32f(gl::Texture& texture, int width, int height, std::string_view label) {
  if (texture && texture.width() == width && texture.height() == height) return;
  texture = gl::Texture(
      gl::TextureInfo{.format = GL_RGBA32F, .width = width, .height = height, .label = label});
}

void dispatch_over(const gl::Texture& texture) {
  glDispatchCompute(static_cast<GLuint>((texture.width() + 7) / 8),
                    static_cast<GLuint>((texture.height() + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace

void Accumulator::add(const ViewSource& view) {
  const gl::Texture& source = *view.texture;
  if (!add_program_) {
    add_program_ = gl::Program::compute("render/accumulate.comp", {{"ACCUMULATE_STEP", "0"}});
    resolve_program_ = gl::Program::compute("render/accumulate.comp", {{"ACCUMULATE_STEP", "1"}});
  }
  if (count_ == 0) {
    ensure_rgba32f(sum_, source.width(), source.height(), "accumulated sum");
    const std::vector<float> zero(4, 0.0f);
    glClearTexImage(sum_.id(), 0, GL_RGBA, GL_FLOAT, zero.data());
    encoding_ = view.encoding;
  } else if (source.width() != sum_.width() || source.height() != sum_.height()) {
    throw std::logic_error("Accumulator::add: sub-frames of different sizes");
  }
  add_program_.use();
  glBindTextureUnit(UNIT_COMPUTE_INPUT, source.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, sum_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  dispatch_over(sum_);
  ++count_;
}

ViewSource Accumulator::result(bool weighted) {
  if (count_ == 0) throw std::logic_error("Accumulator::result: nothing added");
  ensure_rgba32f(resolved_, sum_.width(), sum_.height(), "accumulated view");
  resolve_program_.use();
  glProgramUniform1i(resolve_program_.id(), 0, count_);
  glProgramUniform1i(resolve_program_.id(), 1, weighted ? 1 : 0);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, sum_.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, resolved_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  dispatch_over(resolved_);
  return {&resolved_, encoding_};
}

}  // namespace penumbra
