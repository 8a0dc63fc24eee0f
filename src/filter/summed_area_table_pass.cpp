#include "filter/summed_area_table_pass.hpp"

#include <cmath>
#include <string>

#include "shadow/representation.hpp"
#include "shared/bindings.h"

namespace penumbra {

namespace {
GLuint groups(int size, int local) {
  return static_cast<GLuint>((size + local - 1) / local);
}
}  // namespace

double sat_fixed_point_scale() {
  return std::exp2(std::floor(std::log2(4294967295.0 / kSatMaxBoxArea)));
}

const gl::Program& SummedAreaTablePass::program(const char* path, GLenum format) {
  auto key = std::make_pair(std::string(path), format);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"IMAGE_FORMAT", image_format_qualifier(format)}};
    it = programs_.emplace(key, gl::Program::compute(path, defines)).first;
  }
  return it->second;
}

TexelTraffic SummedAreaTablePass::row_traffic(GLenum source_format) {
  return {static_cast<double>(bytes_per_texel(source_format)),
          static_cast<double>(bytes_per_texel(integer_format_with_channels_of(source_format)))};
}

TexelTraffic SummedAreaTablePass::column_traffic(GLenum source_format) {
  const auto table =
      static_cast<double>(bytes_per_texel(integer_format_with_channels_of(source_format)));
  return {table, table};
}

void SummedAreaTablePass::execute(const gl::Texture& source, gl::GpuProfiler* profiler) {
  const GLenum format = integer_format_with_channels_of(source.format());
  gl::Texture& table = table_;
  gl::ensure_texture_array(table, format, source.width(), source.height(), source.layers(),
                           "summed-area tables");
  const auto layers = static_cast<GLuint>(source.layers());

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "summed-area table");
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatRows);
    const gl::Program& rows = program("filter/sat_rows.comp", format);
    rows.use();
    glProgramUniform1f(rows.id(), 0, static_cast<float>(sat_fixed_point_scale()));
    glBindTextureUnit(UNIT_COMPUTE_INPUT, source.id());
    glBindSampler(UNIT_COMPUTE_INPUT, 0);
    glBindImageTexture(IMAGE_OUTPUT, table.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
    glDispatchCompute(groups(source.height(), 64), layers, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatColumns);
    program("filter/sat_columns.comp", format).use();
    glBindImageTexture(IMAGE_OUTPUT, table.id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    glDispatchCompute(groups(source.width(), 64), layers, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glPopDebugGroup();
}

const gl::Texture& SummedAreaTablePass::box_filtered(int radius) {
  const gl::Texture& sat = table_;
  gl::ensure_texture_array(box_filtered_, GL_RGBA32F, sat.width(), sat.height(), sat.layers(),
                           "SAT box averages");
  const gl::Program& box = program("filter/sat_box.comp", GL_RGBA32F);
  box.use();
  glProgramUniform1i(box.id(), 0, radius);
  glProgramUniform1f(box.id(), 1, static_cast<float>(sat_fixed_point_scale()));
  glBindTextureUnit(UNIT_COMPUTE_INPUT, sat.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindImageTexture(IMAGE_OUTPUT, box_filtered_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(groups(sat.width(), 16), groups(sat.height(), 16),
                    static_cast<GLuint>(sat.layers()));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  return box_filtered_;
}

}  // namespace penumbra
