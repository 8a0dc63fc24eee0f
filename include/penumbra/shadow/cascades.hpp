#pragma once
// Cascaded shadow maps for directional lights: the camera's view frustum
// cut into slices along its depth, each slice with its own orthographic
// shadow view, so texels near the camera are small and far ones large.
// Pure CPU functions, tested without a GPU.
//
// Stability (no shimmering as the camera moves or turns): each cascade's
// extent is set by the bounding sphere of its frustum slice, which does not
// depend on the camera's orientation, with its radius rounded up to a
// coarse geometric grid, so it does not follow small changes of the
// camera's near and far planes; and its origin is snapped to whole texels
// in light space, so a camera move slides the map by whole texels and
// every texel keeps sampling the same scene points.
//
// Tight cascades (--tight-cascades) cover only the geometry their slice
// sees (the receivers), widened by the reach of its blockers through the
// sun's disc: texels typically 1.4 to 2 times finer, with the same
// rounding and snapping, but a size that steps as the camera turns.
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "penumbra/light.hpp"
#include "penumbra/position_span.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "penumbra/shadow/light_view.hpp"

namespace penumbra {

// Split depths C_0 = near < C_1 < ... < C_count = far of the practical split
// scheme (Zhang et al., "Parallel-Split Shadow Maps for Large-scale Virtual
// Environments", VRCIA 2006, eq. 9):
//   C_i = lambda C_log + (1 - lambda) C_uni,
//   C_log = n (f / n)^(i / N), C_uni = n + (f - n) i / N.
std::vector<float> cascade_splits(float near_plane, float far_plane, int count, float lambda);

struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
};

// The smallest sphere holding the eight corners of the camera frustum's
// slice between depths d0 < d1. Its centre lies on the view axis at the
// depth c equidistant from the near and far corners: with k the frustum's
// half-diagonal at unit depth, (c - d0)^2 + d0^2 k^2 = (d1 - c)^2 + d1^2 k^2
// gives c = (d0 + d1)(1 + k^2) / 2, clamped to d1. The radius depends on
// the slice only, not on where the camera looks.
Sphere frustum_slice_sphere(const CameraFrustum& camera, float d0, float d1);

// The radius rounded up to the next step of 2^(1/8) (9 percent): the
// cascade's texel size changes only when the slice's size changes by that
// much.
float quantize_cascade_radius(float radius);

// A light-space coordinate rounded to the nearest multiple of the texel size.
glm::vec2 snap_to_texel(const glm::vec2& p, float texel);

// The camera depth where cascade i's slice begins: split i, moved back over
// the blend band at the end of cascade i - 1 (the last `blend` of its
// depth range), where points read both cascades; the near plane for the
// first.
float cascade_slice_start(std::span<const float> splits, float blend, std::size_t i);

// The orthographic views of the cascades between the splits (splits.size()
// - 1 of them). Each is square and looks down the light's direction with a
// fixed orientation. Its half-width: the quantized radius of the sphere of
// its slice (from cascade_slice_start() to its split) widened by one texel
// for the snapping; or, if `tight` and the slice sees any geometry: half
// the wider side of that geometry's light-space rectangle plus its
// blockers' reach (the tangent of the light's sun_angle / 2 times the
// cascade's depth span), rounded up to the radius grid and widened by 16
// texels (an eighth of the map at most) for the filters and one for the
// snapping.
//
// Depth bounds per cascade, so precision does not depend on the scene's
// size (after Lauritzen et al., "Sample Distribution Shadow Maps", I3D
// 2011, section 4: bounds from what each cascade must shadow): the far end
// is the farthest geometry inside both the cascade's column and its slice
// of the camera frustum (the receivers it covers), the near end the
// nearest geometry anywhere in its column (every caster that can shadow
// them: along a directional light, a shadow's caster lies in the
// receiver's column). Geometry is measured through `bounds`, built over the
// triangles in cascade_light_frame(light) (caster_bounds.hpp): exactly
// where a bounding box lies inside a region, by clipping the triangles
// where a small leaf crosses its edge, and otherwise to within 1/16 of the
// cascade's width, outwards (never nearer than a caster). The cost follows
// the cascades' edges, not the triangle count.
std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits, float blend,
                                         PositionSpan vertices,
                                         std::span<const std::uint32_t> indices,
                                         const CasterHierarchy& bounds, int map_size,
                                         bool tight = false);
// The same, building the bounds for this one fit.
std::vector<LightView> fit_cascade_views(const Light& light, const CameraFrustum& camera,
                                         std::span<const float> splits, float blend,
                                         PositionSpan vertices,
                                         std::span<const std::uint32_t> indices, int map_size,
                                         bool tight = false);

// The frame the cascades of a directional light are fitted in: the light's
// rotation, looking down its direction (origin at the world's).
glm::mat4 cascade_light_frame(const Light& light);

}  // namespace penumbra
