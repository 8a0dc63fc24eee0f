// The one way back from the camera's depth buffer to a position
// (src/render/camera_depth.hpp explains the reversed-Z depth it holds and
// keeps the C++ twin): every pass that reads the G-buffer's depth rebuilds
// positions here and compares distances, never raw depth values.
#pragma once
#include "../shared/bindings.h"

// The position, in the space `inverse_projection` maps to (world for the
// frame's inverse view-projection, camera view for the inverse
// projection), of the point at normalized device coordinates `ndc` with
// window depth `depth` (CAMERA_NEAR_DEPTH at the near plane,
// CAMERA_FAR_DEPTH at the far plane). Clip control GL_ZERO_TO_ONE: window
// depth is NDC z itself.
vec3 position_from_depth(mat4 inverse_projection, vec2 ndc, float depth) {
  vec4 p = inverse_projection * vec4(ndc, depth, 1.0);
  return p.xyz / p.w;
}
