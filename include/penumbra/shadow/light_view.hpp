#pragma once
// Where a light's shadow map looks: its view and projection, fitted to the
// scene, and the depth range [z0, z1] that maps light-space depth to the
// relative depth z-bar = (z - z0) / (z1 - z0) every technique stores.
// Pure CPU functions, tested without a GPU.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>

#include "penumbra/light.hpp"
#include "penumbra/position_span.hpp"
#include "penumbra/shadow/caster_bounds.hpp"

namespace penumbra {

struct LightView {
  glm::mat4 view{1.0f};        // world -> light view space (looking down -z)
  glm::mat4 projection{1.0f};  // light view -> clip space
  glm::mat4 view_projection{1.0f};
  bool perspective = true;
  // Depth z is the distance from the eye (a point light's cube faces, so
  // that z-bar agrees across faces) rather than the depth along -z.
  bool radial = false;
  float z0 = 0.0f;  // nearest light-space depth of the scene
  float z1 = 1.0f;  // farthest light-space depth of the scene
  // World size of one shadow-map texel: at unit depth for a perspective
  // (spot) light, everywhere for an orthographic (directional) one.
  float texel_world = 0.0f;

  // Relative depth z-bar of a world-space point.
  [[nodiscard]] float relative_depth(const glm::vec3& world) const;
  // The depth z of a world-space point (see `radial`).
  [[nodiscard]] float depth(const glm::vec3& world) const;
};

// An up vector for a view looking along `direction`, never parallel to it.
glm::vec3 stable_up(const glm::vec3& direction);

// The depth range [z0, z1] a perspective view stores for geometry seen at
// depths [zmin, zmax] (or, if none was found, a unit range): padded so
// that the surfaces do not touch the clip planes, with the near plane kept
// at least 1e-3 of the far one for depth precision.
void padded_depth_range(bool found, float zmin, float zmax, float& z0, float& z1);

// Fits the light's shadow frustum to the scene's triangles: a spot light's
// perspective frustum covers its cone and its near/far planes hug the
// geometry inside it; a directional light's orthographic box encloses
// every vertex.
LightView fit_light_view(const Light& light, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, int map_size);
// The same for a mesh with `vertices` (each with a glm::vec3 `position`)
// and `indices` members.
template <class Mesh>
requires requires(const Mesh& m) {
  PositionSpan(m.vertices);
  std::span<const std::uint32_t>(m.indices);
}
LightView fit_light_view(const Light& light, const Mesh& mesh, int map_size) {
  return fit_light_view(light, PositionSpan(mesh.vertices), mesh.indices, map_size);
}

// Depth range, in front of the eye of `view`, of the parts of the triangles
// inside the frustum side planes |x| <= kx z, |y| <= ky z of view space (kx,
// ky: tangents of the half-angles). Each triangle is clipped
// Sutherland-Hodgman style, so geometry outside the frustum does not widen
// the range and a large triangle that crosses it still counts where it is
// seen. False if no geometry is inside.
bool frustum_depth_range(const glm::mat4& view, float kx, float ky, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, float& zmin, float& zmax);
// The same through bounds built over the triangles in the world's frame
// (an identity frame: caster_bounds.hpp), in time that does not grow with
// the triangle count; outwards (nearer for zmin, farther for zmax), by a
// few percent of zmin and up to a third or so of zmax.
bool frustum_depth_range(const glm::mat4& view, float kx, float ky, PositionSpan vertices,
                         std::span<const std::uint32_t> indices, const CasterHierarchy& bounds,
                         float& zmin, float& zmax);

}  // namespace penumbra
