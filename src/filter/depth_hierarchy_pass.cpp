#include "penumbra/filter/depth_hierarchy_pass.hpp"

#include <algorithm>
#include <bit>

#include "penumbra/shadow/representation.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

namespace {
constexpr int kHierarchyGroup = 8;   // local_size_x and _y of depth_hierarchy.comp
constexpr double kBoundsBytes = 16;  // GL_RGBA32F

int level_count(int width, int height) {
  return std::bit_width(static_cast<unsigned>(std::max(width, height)));
}
}  // namespace

TexelTraffic DepthHierarchyPass::texel_traffic(GLenum depth_format, int width, int height) {
  if (width <= 0 || height <= 0) return {};
  const double base = static_cast<double>(width) * height;
  double read = bytes_per_texel(depth_format) * base, written = 0.0;
  int w = std::max(width / 2, 1), h = std::max(height / 2, 1);
  const int levels = level_count(w, h);
  for (int level = 0; level < levels; ++level) {
    written += kBoundsBytes * w * h;
    if (level + 1 < levels) read += kBoundsBytes * w * h;
    w = std::max(w / 2, 1);
    h = std::max(h / 2, 1);
  }
  return {read / base, written / base};
}

void DepthHierarchyPass::execute(const gl::Texture& depth_maps) {
  int w = std::max(depth_maps.width() / 2, 1), h = std::max(depth_maps.height() / 2, 1);
  const int levels = level_count(w, h);
  if (gl::ensure_texture_array(hierarchy_, GL_RGBA32F, w, h, depth_maps.layers(),
                               "depth min/max hierarchy", levels)) {
    // Read with texelFetch at every level, bound without a sampler.
    glTextureParameteri(hierarchy_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTextureParameteri(hierarchy_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "depth min/max hierarchy");
  for (int level = 0; level < levels; ++level) {
    if (level == 0) {
      from_depth_.use();
      glBindTextureUnit(UNIT_COMPUTE_INPUT, depth_maps.id());
      glBindSampler(UNIT_COMPUTE_INPUT, 0);
    } else {
      from_level_.use();
      glBindImageTexture(IMAGE_OUTPUT, hierarchy_.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY,
                         GL_RGBA32F);
    }
    glBindImageTexture(IMAGE_OUTPUT_2, hierarchy_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    glDispatchCompute(gl::work_groups(w, kHierarchyGroup), gl::work_groups(h, kHierarchyGroup),
                      static_cast<GLuint>(depth_maps.layers()));
    // The next level reads what this one wrote.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    w = std::max(w / 2, 1);
    h = std::max(h / 2, 1);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glPopDebugGroup();
}

}  // namespace penumbra
