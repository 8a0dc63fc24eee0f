#pragma once
// How far a surface point rebuilt from the depth buffer (as the lighting
// pass and the reference tracer rebuild it) can lie off the triangle the
// GPU rasterized, measured along the surface normal. The reference tracer
// starts its shadow rays that far above the point, so that they clear the
// surface's own triangles without shifting shadows by more than the
// rebuilt position is uncertain anyway: the approach of pbrt-v4 (Pharr,
// Jakob, Humphreys, "Physically Based Rendering", 4th ed., section 6.8.6,
// "Robust Spawned Ray Origins"), which offsets a ray's origin along the
// normal by the bound of its position's floating-point error, with the
// error bound here coming from the depth buffer rather than from a ray's
// intersection.
#include <glm/glm.hpp>

namespace penumbra {

// The window depth's error bound for a GL_DEPTH_COMPONENT32F buffer: half
// an ulp of storage, a few ulps from the vertex transform and perspective
// divide, and a few from interpolating the plane equation, on values
// below 1 (whose ulp is at most 2^-24): 8 ulps of 2^-24 in all.
inline constexpr double kDepthBufferError = 0x1p-21;

// `inverse_view_projection` maps NDC to world space; (x, y) is the pixel
// centre in NDC, `window_depth` the depth buffer's value there, `normal`
// the unit surface normal; the viewport is width x height pixels and the
// rasterizer snaps vertices to 2^-subpixel_bits of a pixel
// (GL_SUBPIXEL_BITS). The bound is the sum, along the normal, of the
// position's moves under the depth's error and under a vertex snap of a
// whole subpixel step in x and in y (a snap moves the triangle's plane in
// window space; moving the pixel by the same step at the same depth gives
// the same plane to first order).
float depth_position_error(const glm::dmat4& inverse_view_projection, glm::dvec2 ndc_xy,
                           double window_depth, glm::vec3 normal, int width, int height,
                           int subpixel_bits);

}  // namespace penumbra
