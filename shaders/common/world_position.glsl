// The world position of the camera's pixel `pixel` from its depth-buffer
// value: every pass that reads the G-buffer's depth rebuilds positions
// here, so the depth convention lives in one place. Needs FrameBlock
// (uniforms.glsl).
#pragma once

vec3 world_position(ivec2 pixel, float depth) {
  vec2 ndc = (vec2(pixel) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  vec4 p = frame.inverse_view_projection * vec4(ndc, depth * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}
