#pragma once
// The terminator model: where a shadow ray from a smooth-shaded triangle
// starts, the one penumbra's traced reference and its techniques' lookups
// share (shaders/scene/smooth_surface.glsl and shaders/render/
// terminator_offset.glsl are this file's GLSL twins), and the path tracer
// they are checked against (Blender Cycles, scripts/pathtrace-check)
// applies.
//
// A flat triangle of a smooth-shaded mesh shadows its neighbours near the
// terminator where the smooth surface its vertex normals describe would
// not (the "shadow terminator" artefact). Hanika ("Hacking the Shadow
// Terminator", Ray Tracing Gems II, 2021, ch. 4) starts the ray on that
// smooth surface. Cycles (kernel/light/sample.h:
// shadow_ray_smooth_surface_offset, shadow_ray_offset) estimates the rise
// by a quadratic patch through the corners' normals, bounded by the
// corners' tangent planes, and applies it only where the light grazes the
// surface. The bound and the grazing rule are what keep a lift in its
// place on surfaces its smooth-surface model does not fit: a leaf card's
// vertex normals, bent ~60 degrees from its face towards a sphere around a
// tree's crown, describe a dome as high as the card is wide, which would
// lift every point past the card above it; facing the light, the card gets
// no lift at all.
#include <glm/glm.hpp>

namespace penumbra {

// Cycles' default "shadow terminator geometry offset": the cosine between
// the shading normal and the light under which shadow rays are lifted
// (shaders/render/terminator_offset.glsl declares it again for GLSL).
inline constexpr float kTerminatorOffsetCutoff = 0.1f;

// How far the point with barycentric weights w of the triangle with
// `corners` and unit vertex `normals` rises along its unit shading normal n
// to the smooth surface: Cycles' quadratic estimate, at least half of it
// and otherwise no higher than the lowest of the corners' linear envelopes
// (each corner's tangent plane raised to clear the other two corners).
// Corner normals are taken on n's side (a double-sided surface seen from
// behind). The rise is along the interpolated, unnormalized normal, as
// Cycles takes it: returned as the length along n. 0 on a flat mesh.
float smooth_surface_rise(const glm::vec3 corners[3], const glm::vec3 normals[3],
                          const glm::vec3& w, const glm::vec3& n);

// Which fraction of the rise a shadow ray towards direction l gets at a
// point with unit shading normal n and triangle normal ng (on n's side):
// all of it at grazing light (n.l + ng.l under the cutoff), none once
// both cosines reach the cutoff (Cycles' shadow_ray_offset, with n.l
// taken at least 0).
float terminator_offset_amount(const glm::vec3& n, const glm::vec3& ng, const glm::vec3& l);

}  // namespace penumbra
