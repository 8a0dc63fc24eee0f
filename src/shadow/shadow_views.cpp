#include "shadow/shadow_views.hpp"

#include "shadow/cube_views.hpp"

namespace penumbra {

LightShadowViews fit_shadow_views(const Light& light, const TriangleMesh& mesh,
                                  const CameraFrustum& camera, const ShadowSettings& settings) {
  LightShadowViews result;
  switch (light.type) {
    case LightType::Spot:
      result.views.push_back(fit_light_view(light, mesh, settings.map_size));
      break;
    case LightType::Point:
      result.views = fit_cube_views(light, mesh.vertices, mesh.indices, settings.map_size,
                                    guard_band_texels(settings, settings.map_size));
      break;
    case LightType::Directional: {
      const std::vector<float> splits = cascade_splits(camera.near_plane, camera.far_plane,
                                                       settings.cascades, settings.cascade_lambda);
      result.views = fit_cascade_views(light, camera, splits, mesh.vertices, settings.map_size);
      result.cascade_end.assign(splits.begin() + 1, splits.end());
      result.cascade_start = splits.front();
      break;
    }
  }
  return result;
}

}  // namespace penumbra
