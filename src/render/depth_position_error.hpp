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

// The window depth's error for a GL_DEPTH_COMPONENT32F buffer, in two
// parts. Relative to the depth itself: half an ulp of storage, the
// perspective divide's rounding and a few ulps from interpolating the
// plane equation, 8 ulps of 2^-24 in all. And relative to the distance
// from the camera: the vertex transform rounds clip z and w to a few ulps
// of the coordinates, so the point slides along its ray by a few 2^-24 of
// its distance however depth is stored (with reversed-Z, clip z near the
// far plane is A z + B with the two terms nearly cancelling: an error of
// 2^-24 of B, which is 2^-24 of the distance once divided by w).
//
// With standard-Z (1 at the far plane, render/camera_depth.hpp) the first
// part dominated: the depth is near 1 everywhere, so 8 ulps there move a
// point at distance z by 2^-21 z^2 / n, 0.5 % of the far plane's distance
// with the near plane at 1e-4 of it. With reversed-Z the depth is n/z
// times (f - z) / (f - n), and 8 of its ulps move the point by 2^-21 z at
// most: the bound is a few 1e-7 of the distance at every depth.
inline constexpr double kDepthRelativeError = 0x1p-21;
inline constexpr double kDistanceRelativeError = 0x1p-21;

// `inverse_view_projection` maps NDC to world space; (x, y) is the pixel
// centre in NDC, `window_depth` the depth buffer's value there, `normal`
// the unit surface normal; the viewport is width x height pixels and the
// rasterizer snaps vertices to 2^-subpixel_bits of a pixel
// (GL_SUBPIXEL_BITS). The bound is the sum, along the normal, of the
// position's moves under the depth's two errors and under a vertex snap
// of a whole subpixel step in x and in y (a snap moves the triangle's plane in
// window space; moving the pixel by the same step at the same depth gives
// the same plane to first order).
float depth_position_error(const glm::dmat4& inverse_view_projection, glm::dvec2 ndc_xy,
                           double window_depth, glm::vec3 normal, int width, int height,
                           int subpixel_bits);

}  // namespace penumbra
