#pragma once
// The pixels that see the scene's ground: a point on one of its plane
// shapes (a scene file's "plane": the grounds and floors), on the plane's
// own side. Shadows measured there are those the objects cast onto the
// ground, apart from the objects' own faces, whose texel density depends
// on how far each face turns from the light rather than on how the light's
// maps are laid out.
#include <cstdint>
#include <vector>

#include "render/surface_points.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Per pixel (row-major, as `surfaces`): 1 where the surface point lies on
// a plane shape (within its rectangle, and off its plane by no more than
// the point's position error plus 1e-5 of the plane's extent) and its
// normal is the plane's (within 1 degree); 0 elsewhere.
std::vector<std::uint8_t> ground_pixels(const Scene& scene, const SurfacePoints& surfaces);

}  // namespace penumbra
