#pragma once
// The running sum of --accumulate's sub-frames on the GPU
// (shaders/render/accumulate.comp): `render` and `compare` add N
// sub-frames and read the result once; the viewer adds one per frame
// while nothing changes and shows the result as it refines. One RGBA32F
// sum and one resolved texture of the view's size; no read-back.
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "render/renderer.hpp"

namespace penumbra {

class Accumulator {
 public:
  // Forgets the sum; the next add() starts a new one.
  void reset() { count_ = 0; }
  // Adds a camera view (Renderer::view_source() after a sub-frame's
  // render) to the sum. Every sub-frame of one sum has the same size.
  void add(const ViewSource& view);
  // Sub-frames in the sum.
  [[nodiscard]] int count() const { return count_; }
  // The mean of the sub-frames so far, or for the shadow view rendered
  // with its source weights (`weighted`: GpuShadow::accumulate_weighted)
  // their weighted mean, in the views' encoding. Valid until the next
  // add() or reset(); needs count() > 0.
  [[nodiscard]] ViewSource result(bool weighted);

 private:
  gl::Program add_program_, resolve_program_;
  gl::Texture sum_, resolved_;
  ViewEncoding encoding_ = ViewEncoding::LinearColor;
  int count_ = 0;
};

}  // namespace penumbra
