// The C++ mirrors of the uniform blocks (shaders/shared/gpu_types.h) match
// the std140 offsets the driver reports.
#include <cstddef>
#include <string>

#include "gpu_fixture.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/shared/bindings.h"
#include "penumbra/shared/gpu_types.h"
#include "shadow/shadow_lookup.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

GLint driver_offset(GLuint program, const std::string& name) {
  GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
  if (index == GL_INVALID_INDEX) return -1;
  const GLenum property = GL_OFFSET;
  GLint offset = -1;
  glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr, &offset);
  return offset;
}

#define EXPECT_OFFSET(program, instance, type, member)                                        \
  EXPECT_EQ(driver_offset(program, instance "." #member), GLint(offsetof(gpu::type, member))) \
      << #type "::" #member

TEST_F(GpuTest, UniformBlocksMatchTheirCppMirrors) {
  // The lighting pass reads every member of every block.
  gl::Program lighting = gl::Program::graphics("common/fullscreen.vert", "render/lighting.frag",
                                               {{"SHADOW_TECHNIQUE", std::to_string(TECHNIQUE_MSM)},
                                                {"SHADOW_FILTER", std::to_string(FILTER_SAT)},
                                                {"MSM_QUANTIZED", "0"},
                                                {"SOFT_SHADOWS", "1"},
                                                {"CONTACT_SHADOWS", "1"}});
  const GLuint p = lighting.id();
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, constant_bias);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, normal_offset);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, max_slope);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, msm_alpha);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, blur_radius);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, sat_scale);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, filter_slope_bias);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, pcf_width);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, pcss_filter_samples);
  EXPECT_OFFSET(p, "shadow_params", GpuShadow, backprojection_cells);
  EXPECT_OFFSET(p, "frame", GpuFrame, inverse_view_projection);
  EXPECT_OFFSET(p, "frame", GpuFrame, camera_position);
  EXPECT_OFFSET(p, "frame", GpuFrame, viewport);
  EXPECT_OFFSET(p, "frame", GpuFrame, options);
  EXPECT_OFFSET(p, "frame", GpuFrame, ambient);
  EXPECT_OFFSET(p, "frame", GpuFrame, contact_length);
  EXPECT_OFFSET(p, "frame", GpuFrame, contact_thickness);
  EXPECT_OFFSET(p, "frame", GpuFrame, contact_steps);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, position_type);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, direction_cos_outer);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, radiance_cos_inner);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, views);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, cascade_end);
  EXPECT_OFFSET(p, "lights[0]", GpuLight, cascade_blend);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, view);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, view_projection);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, inverse_view_projection);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, depth_range);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, source_width);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, perspective);
  EXPECT_OFFSET(p, "shadow_views[0]", GpuShadowView, radial_depth);
  // The array strides are the structs' sizes.
  EXPECT_EQ(driver_offset(p, "lights[1].position_type"), GLint(sizeof(gpu::GpuLight)));
  EXPECT_EQ(driver_offset(p, "shadow_views[1].view"), GLint(sizeof(gpu::GpuShadowView)));
}

// The shadow core's one block (penumbra::ShadowBlock), as the lookup an
// engine includes declares it.
TEST_F(GpuTest, ShadowBlockMatchesItsCppMirror) {
  gl::Program lookup = gl::Program::graphics("common/fullscreen.vert", "test/penumbra_lookup.frag",
                                             shadow_binding_defines({}));
  const GLuint p = lookup.id();
  EXPECT_EQ(driver_offset(p, "penumbra_block.params.constant_bias"),
            GLint(offsetof(gpu::GpuShadowBlock, params)));
  EXPECT_EQ(driver_offset(p, "penumbra_block.params.pcf_samples"),
            GLint(offsetof(gpu::GpuShadowBlock, params) + offsetof(gpu::GpuShadow, pcf_samples)));
  EXPECT_EQ(driver_offset(p, "penumbra_block.params.filter_type"),
            GLint(offsetof(gpu::GpuShadowBlock, params) + offsetof(gpu::GpuShadow, filter_type)));
  EXPECT_OFFSET(p, "penumbra_block", GpuShadowBlock, camera_view);
  EXPECT_OFFSET(p, "penumbra_block", GpuShadowBlock, counts);
  EXPECT_EQ(driver_offset(p, "penumbra_block.lights[0].position_type"),
            GLint(offsetof(gpu::GpuShadowBlock, lights)));
  EXPECT_EQ(driver_offset(p, "penumbra_block.lights[1].position_type"),
            GLint(offsetof(gpu::GpuShadowBlock, lights) + sizeof(gpu::GpuLight)));
  EXPECT_EQ(driver_offset(p, "penumbra_block.views[0].view"),
            GLint(offsetof(gpu::GpuShadowBlock, views)));
  EXPECT_EQ(driver_offset(p, "penumbra_block.views[1].view"),
            GLint(offsetof(gpu::GpuShadowBlock, views) + sizeof(gpu::GpuShadowView)));
  GLint size = 0;
  const GLuint block = glGetProgramResourceIndex(p, GL_UNIFORM_BLOCK, "PenumbraShadowBlock");
  const GLenum property = GL_BUFFER_DATA_SIZE;
  glGetProgramResourceiv(p, GL_UNIFORM_BLOCK, block, 1, &property, 1, nullptr, &size);
  EXPECT_EQ(size, GLint(sizeof(gpu::GpuShadowBlock)));
}

// The virtual shadow maps' block (every virtual light's levels), as the
// marking and allocation passes read it.
TEST_F(GpuTest, VirtualShadowBlockMatchesItsCppMirror) {
  gl::Program mark = gl::Program::compute("shadow/virtual_mark.comp");
  gl::Program allocate = gl::Program::compute("shadow/virtual_allocate.comp");
  EXPECT_EQ(driver_offset(mark.id(), "virtual_shadow.levels[0].view_projection"),
            GLint(offsetof(gpu::GpuVirtualShadow, levels) +
                  offsetof(gpu::GpuShadowView, view_projection)));
  EXPECT_EQ(driver_offset(mark.id(), "virtual_shadow.levels[1].view_projection"),
            GLint(offsetof(gpu::GpuVirtualShadow, levels) + sizeof(gpu::GpuShadowView) +
                  offsetof(gpu::GpuShadowView, view_projection)));
  EXPECT_OFFSET(mark.id(), "virtual_shadow", GpuVirtualShadow, lights);
  EXPECT_OFFSET(mark.id(), "virtual_shadow", GpuVirtualShadow, camera);
  EXPECT_OFFSET(mark.id(), "virtual_shadow", GpuVirtualShadow, params);
  EXPECT_OFFSET(allocate.id(), "virtual_shadow", GpuVirtualShadow, origins);
  EXPECT_OFFSET(allocate.id(), "virtual_shadow", GpuVirtualShadow, previous_origins);
  EXPECT_OFFSET(allocate.id(), "virtual_shadow", GpuVirtualShadow, counts);
  GLint size = 0;
  const GLuint block = glGetProgramResourceIndex(mark.id(), GL_UNIFORM_BLOCK, "VirtualShadowBlock");
  const GLenum property = GL_BUFFER_DATA_SIZE;
  glGetProgramResourceiv(mark.id(), GL_UNIFORM_BLOCK, block, 1, &property, 1, nullptr, &size);
  EXPECT_EQ(size, GLint(sizeof(gpu::GpuVirtualShadow)));
}

TEST_F(GpuTest, SsaoBlockMatchesItsCppMirror) {
  gl::Program ssao = gl::Program::compute("render/ssao.comp");
  const GLuint p = ssao.id();
  EXPECT_OFFSET(p, "ssao", GpuSsao, view);
  EXPECT_OFFSET(p, "ssao", GpuSsao, projection);
  EXPECT_OFFSET(p, "ssao", GpuSsao, inverse_projection);
  EXPECT_EQ(driver_offset(p, "ssao.kernel[0]"), GLint(offsetof(gpu::GpuSsao, kernel)));
  EXPECT_OFFSET(p, "ssao", GpuSsao, size);
  EXPECT_OFFSET(p, "ssao", GpuSsao, radius);
  EXPECT_OFFSET(p, "ssao", GpuSsao, bias);
  EXPECT_OFFSET(p, "ssao", GpuSsao, range);
  EXPECT_OFFSET(p, "ssao", GpuSsao, sample_count);
  EXPECT_OFFSET(p, "ssao", GpuSsao, scale);
  const GLuint kernel = glGetProgramResourceIndex(p, GL_UNIFORM, "ssao.kernel[0]");
  const GLenum stride_property = GL_ARRAY_STRIDE;
  GLint stride = -1;
  glGetProgramResourceiv(p, GL_UNIFORM, kernel, 1, &stride_property, 1, nullptr, &stride);
  EXPECT_EQ(stride, GLint(sizeof(glm::vec4)));
  gl::Program blur = gl::Program::compute("render/ssao_blur.comp", {{"AXIS", "0"}});
  EXPECT_OFFSET(blur.id(), "ssao", GpuSsao, blur_radius);
}

}  // namespace
}  // namespace penumbra
