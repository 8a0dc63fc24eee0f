#pragma once
// A point light's shadow: the six faces of a cube around the light, each a
// perspective view storing radial depth (the distance from the light), so
// that z-bar is one continuous function of the point across all faces and
// the shadow has no step where the faces meet. Pure CPU functions, tested
// without a GPU.
//
// Seams: a filter kernel near a face's edge would read texels beyond it,
// which a 90-degree face does not have (they belong to the neighbouring
// face). A guard band widens each face's frustum by the filter's reach plus
// a margin, in texels, so such a kernel reads valid scene depths from its
// own face; the face is still chosen by the major axis of the direction
// from the light, exactly as without the band.
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "penumbra/light.hpp"
#include "penumbra/position_span.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/light_view.hpp"

namespace penumbra {

inline constexpr int kCubeFaces = 6;

// Face f's axis (0..5: +x, -x, +y, -y, +z, -z) and its up vector (those of
// OpenGL's cube maps).
glm::vec3 cube_face_axis(int face);
glm::vec3 cube_face_up(int face);
// The face whose axis is the major axis of d (ties: x before y before z), as
// shaders/shadow/view_select.glsl's cube_face() picks it.
int cube_face(const glm::vec3& d);

// Half-width tan(fov / 2) of a face whose map of `map_size` texels has
// `guard_texels` texels on each side beyond the 90-degree face:
// a texel is 2t / size wide at unit depth, and the band g texels wide
// covers t - 1 of it, so g 2t / size = t - 1, t = 1 / (1 - 2 g / size).
float guard_band_half_width(int map_size, float guard_texels);
// The face's full field of view in radians, 2 atan(t).
float guard_band_fov(int map_size, float guard_texels);
// The guard band the settings need: how far (in texels) the technique's
// filter reaches from the lookup texel, plus a margin for the normal
// offset and bilinear taps; 0 with --guard-band off. At most map_size / 8
// texels (a quarter of the face's resolution spent on the band).
float guard_band_texels(const ShadowMapSettings& settings, int map_size);

// Nearest and farthest distance from `center` to the triangles (the
// nearest point may lie inside a triangle, the farthest is a vertex).
// False without triangles.
bool radial_depth_range(const glm::vec3& center, PositionSpan vertices,
                        std::span<const std::uint32_t> indices, float& zmin, float& zmax);

// The six face views of a point light at `light.position`, radial depth
// range fitted to the scene and shared by all faces.
std::vector<LightView> fit_cube_views(const Light& light, PositionSpan vertices,
                                      std::span<const std::uint32_t> indices, int map_size,
                                      float guard_texels);

}  // namespace penumbra
