#pragma once
// glTF's KHR_lights_punctual lights as penumbra's lights.
//
// glTF gives a point or spot light's luminous intensity in candela and a
// directional light's illuminance in lux, and lights a surface facing the
// light with E = I / d^2 (point, spot: inside the inner cone) or E = the
// illuminance (directional). penumbra's Light::intensity is the same
// quantity in its own unit: a spot or point light's intensity is the
// irradiance at 1 m (falling off as 1 / d^2), a directional light's the
// irradiance, and irradiance 1 lights a white surface facing the light
// to full white. One candela is taken to be intensity 1 and one lux
// irradiance 1 (kIntensityPerCandela, kIrradiancePerLux), so that glTF's
// formulas give penumbra's irradiance directly; --light-intensity scales
// a light that comes out too bright or too dim. The colour is glTF's
// colour; colour times intensity is kept exactly (penumbra's colour is
// scaled to a largest channel of 1).
//
// Spot cones: glTF's outerConeAngle is penumbra's cone (where the light
// ends), innerConeAngle its inner cone (where the fall-off starts), both
// kept within penumbra's 1 to 80 degrees. Between them glTF ramps the
// square of a linear function of the cosine, penumbra a smoothstep of the
// cosine: both 1 inside the inner cone and 0 outside the outer one.
// glTF's "range" (a cut-off distance) is not modelled: the light falls
// off as 1 / d^2 everywhere, as glTF's own formula does without it.
#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace penumbra {

inline constexpr float kIntensityPerCandela = 1.0f;
inline constexpr float kIrradiancePerLux = 1.0f;

// The range of a spot light's cone half-angle penumbra draws (the same as
// a scene file's "cone").
inline constexpr float kMinSpotConeDegrees = 1.0f;
inline constexpr float kMaxSpotConeDegrees = 80.0f;

enum class GltfLightType { Directional, Point, Spot };

// The light with glTF's colour, intensity (candela or lux) and, for a spot
// light, cone angles in radians; placed at the origin, shining down -z
// (the light's node places it).
Light light_from_gltf(GltfLightType type, const glm::vec3& color, float intensity,
                      float inner_cone_radians, float outer_cone_radians);

}  // namespace penumbra
