#include "penumbra/shadow/shadow_views.hpp"

#include "shadow/cube_views.hpp"

namespace penumbra {

ShadowViewInputs shadow_view_inputs(const Light& light, const CameraFrustum& camera,
                                    const ShadowMapSettings& settings) {
  ShadowViewInputs inputs;
  inputs.light = light;
  // The source's size widens penumbrae, not views: a new size refits
  // nothing, but for cascades fitted to their receivers, which keep the
  // reach of the sun's disc around them.
  inputs.light.light_size = Light{}.light_size;
  if (light.type != LightType::Directional || !settings.tight_cascades) {
    inputs.light.sun_angle = Light{}.sun_angle;
  }
  inputs.map_size = settings.map_size;
  switch (light.type) {
    case LightType::Spot:
      break;
    case LightType::Point:
      inputs.guard_band_texels = guard_band_texels(settings, settings.map_size);
      break;
    case LightType::Directional:
      inputs.camera = camera;
      inputs.cascades = settings.cascades;
      inputs.cascade_lambda = settings.cascade_lambda;
      inputs.cascade_blend = settings.cascade_blend;
      inputs.tight_cascades = settings.tight_cascades;
      break;
  }
  return inputs;
}

LightShadowViews fit_shadow_views(const ShadowViewInputs& inputs, PositionSpan vertices,
                                  std::span<const std::uint32_t> indices) {
  CasterBoundsCache cache;
  return fit_shadow_views(inputs, vertices, indices, cache);
}

LightShadowViews fit_shadow_views(const ShadowViewInputs& inputs, PositionSpan vertices,
                                  std::span<const std::uint32_t> indices,
                                  CasterBoundsCache& cache) {
  const Light& light = inputs.light;
  LightShadowViews result;
  switch (light.type) {
    case LightType::Spot:
      result.views.push_back(fit_light_view(light, vertices, indices, inputs.map_size));
      break;
    case LightType::Point:
      result.views =
          fit_cube_views(light, vertices, indices, inputs.map_size, inputs.guard_band_texels);
      break;
    case LightType::Directional: {
      const CameraFrustum& camera = inputs.camera;
      const std::vector<float> splits = cascade_splits(camera.near_plane, camera.far_plane,
                                                       inputs.cascades, inputs.cascade_lambda);
      const CasterHierarchy& bounds = cache.bounds(vertices, indices, cascade_light_frame(light));
      result.views = fit_cascade_views(light, camera, splits, inputs.cascade_blend, vertices,
                                       indices, bounds, inputs.map_size, inputs.tight_cascades);
      result.cascade_end.assign(splits.begin() + 1, splits.end());
      result.cascade_start = splits.front();
      break;
    }
  }
  return result;
}

}  // namespace penumbra
