#pragma once
// The camera's depth buffer: what its values mean, and the one way back
// from a value to a position. Everything that reads the G-buffer's depth
// (the lighting pass, SSAO, the reference tracer's surface points, the
// tests) goes through position_from_depth() here or its GLSL twin in
// shaders/render/camera_depth.glsl; nothing compares raw depth values.
//
// Reversed-Z: clip control GL_ZERO_TO_ONE, window depth CAMERA_NEAR_DEPTH
// (1) at the near plane falling to CAMERA_FAR_DEPTH (0) at the far plane,
// cleared to 0, tested GL_GREATER (GBufferPass). A 32-bit float depth
// d = n (f - z) / (z (f - n)) keeps float's relative precision at every
// distance z: the floats crowd towards 0 as 1/z spreads the far distances
// there (Lapidous and Jiao, "Optimal Depth Buffer for Low-Cost Graphics
// Hardware", 1999; Reed, "Depth Precision Visualized", 2015). Standard-Z
// (1 at the far plane) stored them near 1, where a float's step is 2^-24:
// with the near plane at 1e-4 of the far one, one step there is 6e-4 of
// the distance.
//
// The far plane is finite (at depth 0, not at infinity): the renderer
// fits it to the geometry in view anyway, the cascades split the range up
// to it, a scene file's zfar clips there, and the far plane stays a point
// (depth 0 unprojects to a finite position) for rays built from depth.
// Infinite far (z_clip = n, w = z) would avoid the cancellation of clip
// z = A z_view + B near the far plane, but that costs 2^-24 of B, which
// is 2^-24 of the distance once converted: the relative precision the
// perspective divide leaves anyway (tests/unit/depth_position_error_test.cpp).
#include <glm/glm.hpp>

#include "penumbra/shared/bindings.h"

namespace penumbra {

// The camera's projection: view space (right-handed, looking down -z) to
// clip space with the reversed depth above; `fov_y` in radians.
glm::mat4 camera_perspective(float fov_y, float aspect, float near_plane, float far_plane);

// The position (in the space `inverse_projection` maps to: world for the
// inverse view-projection, camera view for the inverse projection) of the
// point with normalized device coordinates (x, y) and window depth
// `depth`, as read from the camera's depth buffer.
glm::dvec3 position_from_depth(const glm::dmat4& inverse_projection, glm::dvec2 ndc_xy,
                               double depth);

}  // namespace penumbra
