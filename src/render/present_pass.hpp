#pragma once
// Draws a view's texture into a window's framebuffer, encoded as the PNG
// writer encodes it, fitted into a rectangle with its aspect ratio kept.
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "render/renderer.hpp"

namespace penumbra {

// A rectangle of a framebuffer, in pixels from its bottom-left corner.
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
  bool operator==(const PixelRect&) const = default;
};

// The largest rectangle of the source's aspect ratio centred in `target`.
PixelRect fit_rect(int source_width, int source_height, const PixelRect& target);

class PresentPass {
 public:
  PresentPass();

  // Draws into `framebuffer` (0: the window's) inside fit_rect(source, target).
  // Leaves the rest of `target` untouched.
  void execute(const ViewSource& source, GLuint framebuffer, const PixelRect& target);

 private:
  gl::Program program_;
  gl::VertexArray empty_vao_;
  gl::Sampler nearest_;
  gl::Sampler bilinear_;
};

}  // namespace penumbra
