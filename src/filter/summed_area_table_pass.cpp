#include "penumbra/filter/summed_area_table_pass.hpp"

#include <cmath>
#include <string>

#include "penumbra/gl/context.hpp"
#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"
#include "shared/filter_tiles.h"

namespace penumbra {

SatScan preferred_sat_scan(std::string_view renderer) {
  return gl::is_cpu_rasterizer(renderer) ? SatScan::Serial : SatScan::Parallel;
}

SummedAreaTablePass::SummedAreaTablePass() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  scan_ = preferred_sat_scan(renderer != nullptr ? renderer : "");
}

double sat_fixed_point_scale() {
  return std::exp2(std::floor(std::log2(4294967295.0 / kSatMaxBoxArea)));
}

const gl::Program& SummedAreaTablePass::program(const char* path, GLenum format, int axis) {
  auto key = std::make_tuple(std::string(path), format, axis);
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    gl::Defines defines = {{"IMAGE_FORMAT", image_format_qualifier(format)}};
    if (axis >= 0) defines.push_back({"AXIS", std::to_string(axis)});
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
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "summed-area table");
  if (scan_ == SatScan::Parallel) {
    scan_parallel(source, format, profiler);
  } else {
    scan_serial(source, format, profiler);
  }
  glPopDebugGroup();
}

void SummedAreaTablePass::scan_parallel(const gl::Texture& source, GLenum format,
                                        gl::GpuProfiler* profiler) {
  const auto layers = static_cast<GLuint>(source.layers());
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatRows);
    const gl::Program& rows = program("filter/sat_scan.comp", format, 0);
    rows.use();
    glProgramUniform1f(rows.id(), 0, static_cast<float>(sat_fixed_point_scale()));
    glBindTextureUnit(UNIT_COMPUTE_INPUT, source.id());
    glBindSampler(UNIT_COMPUTE_INPUT, 0);
    glBindImageTexture(IMAGE_OUTPUT, table_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
    glDispatchCompute(gl::work_groups(source.height(), SAT_TILE_ACROSS), 1, layers);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatColumns);
    program("filter/sat_scan.comp", format, 1).use();
    glBindImageTexture(IMAGE_OUTPUT, table_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    glDispatchCompute(gl::work_groups(source.width(), SAT_TILE_ACROSS), 1, layers);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
}

void SummedAreaTablePass::scan_serial(const gl::Texture& source, GLenum format,
                                      gl::GpuProfiler* profiler) {
  gl::Texture& table = table_;
  const auto layers = static_cast<GLuint>(source.layers());
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatRows);
    const gl::Program& rows = program("filter/sat_rows.comp", format);
    rows.use();
    glProgramUniform1f(rows.id(), 0, static_cast<float>(sat_fixed_point_scale()));
    glBindTextureUnit(UNIT_COMPUTE_INPUT, source.id());
    glBindSampler(UNIT_COMPUTE_INPUT, 0);
    glBindImageTexture(IMAGE_OUTPUT, table.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, format);
    glDispatchCompute(gl::work_groups(source.height(), 64), layers, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  {
    gl::GpuPassScope timed(profiler, gl::GpuPass::SatColumns);
    program("filter/sat_columns.comp", format).use();
    glBindImageTexture(IMAGE_OUTPUT, table.id(), 0, GL_TRUE, 0, GL_READ_WRITE, format);
    glDispatchCompute(gl::work_groups(source.width(), 64), layers, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
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
  glDispatchCompute(gl::work_groups(sat.width(), 16), gl::work_groups(sat.height(), 16),
                    static_cast<GLuint>(sat.layers()));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  return box_filtered_;
}

}  // namespace penumbra
