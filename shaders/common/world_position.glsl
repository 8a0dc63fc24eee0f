// The world position of the camera's pixel `pixel` from its depth-buffer
// value, through the one reconstruction (shaders/render/camera_depth.glsl):
// every pass that reads the G-buffer's depth for world positions calls
// this, so the depth convention lives in one place. Needs FrameBlock
// (uniforms.glsl).
#pragma once
#include "../render/camera_depth.glsl"

vec3 world_position(ivec2 pixel, float depth) {
  vec2 ndc = (vec2(pixel) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  return position_from_depth(frame.inverse_view_projection, ndc, depth);
}
