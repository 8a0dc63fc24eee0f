#pragma once
// A light's shadow views: the 2D maps its shadow is read from, each one
// layer of the shadow-map arrays. A spot light has one perspective view;
// a point light six, the faces of a cube (cube_views.hpp); a directional
// light one orthographic view per cascade (cascades.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "penumbra/light.hpp"
#include "penumbra/position_span.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/cascades.hpp"
#include "penumbra/shadow/light_view.hpp"

namespace penumbra {

struct LightShadowViews {
  std::vector<LightView> views;
  // Directional lights: the camera depth where each cascade ends (the last
  // one at the camera's far plane), and where the first begins.
  std::vector<float> cascade_end;
  float cascade_start = 0.0f;
};

// What fit_shadow_views() reads besides the scene's triangles: equal inputs
// give equal views, so a renderer refits a light only when they change (a
// spot or point light's fit clips every triangle of the scene: tens of
// milliseconds for a million). Inputs a light type does not use keep their
// defaults, so a spot or point light does not refit when the camera moves;
// a directional light's cascades do, through caster bounds.
struct ShadowViewInputs {
  Light light;
  int map_size = 0;
  float guard_band_texels = 0.0f;  // point lights
  CameraFrustum camera;            // directional lights: the cascades
  int cascades = 0;
  float cascade_lambda = 0.0f;
  float cascade_blend = 0.0f;
  bool tight_cascades = false;
  bool operator==(const ShadowViewInputs&) const = default;
};
ShadowViewInputs shadow_view_inputs(const Light& light, const CameraFrustum& camera,
                                    const ShadowMapSettings& settings);

// Fits the light's views to the scene (and, for a directional light's
// cascades, to the camera).
LightShadowViews fit_shadow_views(const ShadowViewInputs& inputs, PositionSpan vertices,
                                  std::span<const std::uint32_t> indices);
// The same, the cascades fitted through bounds kept in `cache` for the
// same arrays (caster_bounds.hpp), so a camera move refits them in time
// that does not grow with the triangle count.
LightShadowViews fit_shadow_views(const ShadowViewInputs& inputs, PositionSpan vertices,
                                  std::span<const std::uint32_t> indices, CasterBoundsCache& cache);
// The same for a mesh with `vertices` (each with a glm::vec3 `position`)
// and `indices` members.
template <class Mesh>
requires requires(const Mesh& m) {
  PositionSpan(m.vertices);
  std::span<const std::uint32_t>(m.indices);
}
LightShadowViews fit_shadow_views(const ShadowViewInputs& inputs, const Mesh& mesh) {
  return fit_shadow_views(inputs, PositionSpan(mesh.vertices), mesh.indices);
}

}  // namespace penumbra
