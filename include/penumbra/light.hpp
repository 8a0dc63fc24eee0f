#pragma once
// What the shadow core needs to know of a light and of the camera whose
// view it shadows. An engine fills these from its own light and camera
// types; penumbra's own scenes (src/scene/scene.hpp) use them as they are.
#include <array>
#include <glm/glm.hpp>
#include <string_view>
#include <utility>

namespace penumbra {

enum class LightType { Spot, Directional, Point };

inline constexpr std::array<std::pair<LightType, std::string_view>, 3> kLightTypeNames{{
    {LightType::Spot, "spot"},
    {LightType::Directional, "directional"},
    {LightType::Point, "point"},
}};

struct Light {
  LightType type = LightType::Spot;
  glm::vec3 position{0.0f, 10.0f, 0.0f};   // spot and point
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // spot and directional: the way the light shines
  glm::vec3 color{1.0f};                   // linear RGB
  // spot, point: radiant intensity (irradiance at 1 m, falling off as 1 / d^2);
  // directional: irradiance
  float intensity = 1.0f;
  float cone_degrees = 35.0f;        // spot: half-angle where the light ends
  float inner_cone_degrees = 28.0f;  // spot: half-angle where the fall-off starts
  // The source's size, which sets the penumbra's width (pcss,
  // backprojection, --soft, accumulation and the traced reference): a spot
  // light's source is a square this wide facing its direction, a point
  // light's a sphere of this diameter, in world units (0: a point, hard
  // shadows).
  float light_size = 0.5f;
  // A directional light's source: the disc of directions this many degrees
  // across (the sun's is about 0.53; 0: one direction, hard shadows).
  float sun_angle = 1.0f;
  bool operator==(const Light&) const = default;
};

// The camera a directional light's cascades follow.
struct CameraFrustum {
  glm::vec3 position{0.0f};
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // unit view direction
  glm::vec3 up{0.0f, 1.0f, 0.0f};        // the camera's up vector (not parallel to forward)
  float fov_y = 0.785f;                  // vertical field of view, radians
  float aspect = 1.0f;                   // width / height
  float near_plane = 0.1f;               // depths along `forward`
  float far_plane = 100.0f;
  bool operator==(const CameraFrustum&) const = default;
};

}  // namespace penumbra
