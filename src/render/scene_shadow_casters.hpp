#pragma once
// The renderer's shadow casters: its scene drawn into one shadow view's
// layer (ShadowMapPass), opaque surfaces and cut-outs (alpha-tested or
// single-sided, whose fragments may be discarded) each with a program of
// their own, so opaque ones keep early depth testing.
#include "penumbra/gl/program.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

class SceneShadowCasters {
 public:
  SceneShadowCasters();

  // Draws the scene from shadow view `view` of the shadow-views block
  // (which must be bound).
  void draw(const GpuScene& scene, int view) const;

 private:
  gl::Program program_;          // opaque surfaces
  gl::Program cut_out_program_;  // alpha-tested and single-sided ones
};

}  // namespace penumbra
