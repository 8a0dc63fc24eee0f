#pragma once
// The engine's camera depth buffer, as virtual shadow maps read it: their
// pages are the ones the camera's pixels look up, found from each pixel's
// world position (ShadowMaps::update(), VirtualShadowPass). A GL name and
// the convention the engine drew it with; no GL header.
#include <cstdint>
#include <glm/glm.hpp>

namespace penumbra {

// The clip-space depth range the engine's depth was drawn with
// (glClipControl's depth mode): window depth d is NDC z = 2 d - 1
// (NegativeOneToOne, OpenGL's default) or NDC z = d (ZeroToOne, the
// reversed-Z setup).
enum class ClipDepth { NegativeOneToOne, ZeroToOne };

struct CameraDepthBuffer {
  // A 2D texture holding the camera's window depth in its red channel at
  // level 0 (a depth texture, or R32F), read texel by texel; width x
  // height pixels. It must hold the frame's depth when ShadowMaps::render()
  // runs (marking reads it there). 0: none (no virtual maps).
  std::uint32_t texture = 0;  // a GLuint
  int width = 0;
  int height = 0;
  // World -> clip, the engine's projection times its view, as the depth
  // was drawn (any projection: standard, infinite or reversed-Z).
  glm::mat4 view_projection{1.0f};
  ClipDepth clip_depth = ClipDepth::NegativeOneToOne;
  // The window depth of pixels that see nothing (the value the depth
  // buffer was cleared to): 1, or 0 with reversed-Z. Those pixels mark
  // no page.
  float background_depth = 1.0f;
  // Optional: a 2D texture of the same size holding each pixel's unit
  // world-space normal in rgb, the one the engine's lookup is given (the
  // level a lookup reads leans on the receiver's slope to the camera and
  // the light). 0: marking takes the surface's normal from the depth
  // buffer's neighbouring pixels.
  std::uint32_t normal_texture = 0;  // a GLuint
  bool operator==(const CameraDepthBuffer&) const = default;
};

}  // namespace penumbra
