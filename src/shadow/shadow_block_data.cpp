#include "penumbra/shadow/shadow_block_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/shadow/representation.hpp"

namespace penumbra {

int light_type_define(LightType type) {
  switch (type) {
    case LightType::Spot:
      return LIGHT_SPOT;
    case LightType::Directional:
      return LIGHT_DIRECTIONAL;
    case LightType::Point:
      return LIGHT_POINT;
  }
  return LIGHT_SPOT;
}

gpu::GpuLight gpu_light(const Light& light, const LightShadowViews& views, int first_view,
                        const ShadowMapSettings& shadow) {
  gpu::GpuLight g{};
  g.position_type = glm::vec4(light.position, light_type_define(light.type));
  g.direction_cos_outer =
      glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.cone_degrees)));
  const float inner = std::min(light.inner_cone_degrees, light.cone_degrees - 0.01f);
  g.radiance_cos_inner = glm::vec4(light.color * light.intensity, std::cos(glm::radians(inner)));
  g.views = glm::ivec4(first_view, static_cast<int>(views.views.size()), 0, 0);
  for (std::size_t c = 0; c < views.cascade_end.size() && c < MAX_CASCADES; ++c) {
    g.cascade_end[static_cast<int>(c)] = views.cascade_end[c];
  }
  g.cascade_blend = glm::vec4(shadow.cascade_blend, views.cascade_start, 0.0f, 0.0f);
  return g;
}

gpu::GpuShadowView gpu_shadow_view(const Light& light, const LightView& view,
                                   const ShadowMapSettings& shadow) {
  gpu::GpuShadowView g{};
  g.view = view.view;
  g.view_projection = view.view_projection;
  g.inverse_view_projection = glm::inverse(view.view_projection);
  g.depth_range =
      glm::vec4(view.z0, view.z1, view.texel_world, static_cast<float>(shadow.map_size));
  g.source_width = light.type == LightType::Directional
                       ? 2.0f * std::tan(glm::radians(0.5f * light.sun_angle))
                       : light.light_size;
  g.perspective = view.perspective ? 1 : 0;
  g.radial_depth = view.radial ? 1 : 0;
  return g;
}

gpu::GpuShadow gpu_shadow_params(const ShadowMapSettings& shadow) {
  gpu::GpuShadow block{};
  block.constant_bias = shadow.constant_bias;
  block.slope_bias = shadow.slope_bias;
  block.normal_offset = shadow.normal_offset;
  block.max_slope = shadow.max_slope;
  block.esm_c = shadow.esm_c;
  // The fixed-point summed-area table keeps 17 bits per value, about what
  // 16-bit moments keep: both need the larger moment bias.
  block.msm_alpha = uses_quantized_moments(shadow) ? shadow.msm16_alpha : shadow.msm_alpha;
  block.bleed_reduction = shadow.bleed_reduction;
  block.vsm_min_variance = shadow.vsm_min_variance;
  // Only the filterable techniques filter; the others (and their reference) test single texels.
  block.blur_radius = is_filterable(shadow.technique) ? shadow.blur : 0;
  block.sat_scale = static_cast<float>(sat_fixed_point_scale());
  block.filter_type = filter_define(shadow);
  block.soft_moments = shadow.soft && block.filter_type == FILTER_SAT ? 1 : 0;
  block.filter_slope_bias = shadow.filter_slope_bias;
  block.pcf_width = shadow.pcf_width;
  block.pcf_samples = shadow.pcf_samples;
  block.pcss_blocker_samples = shadow.pcss_blocker_samples;
  block.pcss_filter_samples = shadow.pcss_filter_samples;
  block.two_moment_blockers = shadow.soft_two_moment_blockers ? 1 : 0;
  block.backprojection_cells = shadow.backprojection_cells;
  block.evsm_positive = shadow.evsm_positive;
  block.evsm_negative = shadow.evsm_negative;
  return block;
}

}  // namespace penumbra
