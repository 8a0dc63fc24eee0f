#pragma once
// A light's virtual shadow maps (docs/rendering.md, "Virtual shadow
// maps"), in pages of 128^2 texels. A directional light's: a clipmap of
// orthographic levels down the light, each 16,384^2 virtual texels in
// 128 x 128 pages, level l's texel 2^l times level 0's, every level
// centred on the camera and snapped to whole pages. A spot light's: one
// perspective map of 16,384^2 texels over its conventional map's
// projection, with mip levels down to one page (level m: 16,384 / 2^m
// texels a side, from page (0, 0)). Pure CPU functions, tested without a
// GPU; the shaders' twins are in shaders/shadow/virtual_lookup.glsl.
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "penumbra/light.hpp"
#include "penumbra/position_span.hpp"
#include "penumbra/shadow/caster_bounds.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "penumbra/shared/bindings.h"

namespace penumbra {

inline constexpr int kVirtualPageTexels = VIRTUAL_PAGE_TEXELS;
inline constexpr int kVirtualPages = VIRTUAL_PAGES;
inline constexpr int kVirtualTexels = kVirtualPageTexels * kVirtualPages;
inline constexpr int kMaxVirtualLevels = MAX_VIRTUAL_LEVELS;
inline constexpr int kVirtualSpotLevels = VIRTUAL_SPOT_LEVELS;
inline constexpr int kMaxVirtualViews = MAX_VIRTUAL_VIEWS;

struct VirtualLevel {
  // Orthographic, over exactly the level's 128 x 128 pages (a clipmap
  // level), or the spot's perspective view (a mip level); texel_world is
  // the level's texel (at unit depth for a spot), z0..z1 its depth range.
  LightView view;
  // The world page (light-space xy / page size, floored) of the level's
  // first page: its pages are origin + [0, 128)^2. (0, 0) for a spot.
  glm::ivec2 origin{0};
  // Texels along a side: kVirtualTexels, or a spot's mip level's.
  int texels = kVirtualTexels;
  bool operator==(const VirtualLevel& o) const {
    return origin == o.origin && texels == o.texels && view.z0 == o.view.z0 &&
           view.z1 == o.view.z1 && view.texel_world == o.view.texel_world &&
           view.view == o.view.view && view.projection == o.view.projection;
  }
};

// A light's virtual maps: a directional light's clipmap, or a spot light's
// mip levels (fit_virtual_spot_map).
struct VirtualClipmap {
  std::vector<VirtualLevel> levels;
  // Level 0's texel, world units (a power of two); a spot's at unit depth.
  float texel0 = 0.0f;
  float pixel_angle = 0.0f;              // a pixel's footprint per unit of camera distance
  glm::vec3 camera{0.0f};                // where footprints are measured from
  glm::vec3 forward{0.0f, 0.0f, -1.0f};  // the camera's unit view direction
};

// A pixel's footprint per unit of distance from the camera:
// 2 tan(fov_y / 2) / height.
float pixel_footprint_per_distance(const CameraFrustum& camera, int image_height);

// Fits the clipmap to the camera: kMaxVirtualLevels levels, the
// coarsest's texel the power of two at or below the footprint at the far
// plane (so level 0's is below the footprint at any near plane), each
// centred on the camera snapped to whole pages, its depth range from the
// casters in its column (through `bounds`, built over the triangles in
// cascade_light_frame(light)), snapped to a coarse grid as cascades' are.
// With the `previous` frame's clipmap (of the same light), level 0's texel
// and each level's depth range are kept while they still serve (the texel
// no larger than the one fitted nor smaller than a quarter of it; the
// range holding the new one and at most twice as deep), so that an
// orbiting camera, whose far plane and levels' columns change a little
// every frame, keeps its cached pages.
VirtualClipmap fit_virtual_clipmap(const Light& light, const CameraFrustum& camera,
                                   int image_height, PositionSpan vertices,
                                   std::span<const std::uint32_t> indices,
                                   const CasterHierarchy& bounds,
                                   const VirtualClipmap* previous = nullptr);

// A spot light's virtual map over its conventional view `spot` (fitted
// by fit_light_view): kVirtualSpotLevels levels with its view and
// projection, level m of kVirtualTexels / 2^m texels a side. The depth
// range is `spot`'s, widened by an eighth of its width at each end; with
// the `previous` frame's map (of the same light) the previous range is
// kept while it still holds the new one and is at most twice as deep, so
// that a caster moving inside the cone renders only its own pages again.
VirtualClipmap fit_virtual_spot_map(const LightView& spot, const CameraFrustum& camera,
                                    int image_height, const VirtualClipmap* previous = nullptr);

// log2 of the largest texel that gives the pixel at `world`, on a receiver
// with unit normal `normal`, one texel per pixel, over the first level's
// texel there: the pixel's footprint from its distance and its angle off
// the view axis, made smaller where the receiver turns from the light
// more than from the camera (at most four times).
// virtual_level_coordinate() in shaders/shadow/virtual_lookup.glsl
// derives it.
float virtual_level_coordinate(const VirtualClipmap& clipmap, const glm::vec3& world,
                               const glm::vec3& normal);

// The level a point at `world` reads under level bias `bias` (half levels
// finer; the GPU's allocation picks it per frame, VirtualPageStats::bias):
// the finest whose texel gives the pixel one texel, bias / 2 levels finer
// still (virtual_level_biased() in the shaders).
int virtual_level_of(const VirtualClipmap& clipmap, const glm::vec3& world, const glm::vec3& normal,
                     int bias = 0);

// The page-table slot (0..127 on each axis) of world page `page`: the
// table is addressed modulo 128 in the world's page grid.
glm::ivec2 virtual_page_slot(glm::ivec2 page);

// Level `level`'s world pages that the world-space box [lo, hi] covers in
// light space (a spot level's: its pages the box's projection covers, all
// of them when the box reaches behind the light), clipped to the level:
// {first, last} inclusive; empty (first > last) when the box misses it.
std::pair<glm::ivec2, glm::ivec2> virtual_pages_of_box(const VirtualLevel& level,
                                                       const glm::vec3& lo, const glm::vec3& hi);

}  // namespace penumbra
