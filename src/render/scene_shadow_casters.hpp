#pragma once
// The renderer's shadow casters: its scene drawn into one shadow view's
// layer (ShadowMapPass), opaque surfaces and cut-outs (alpha-tested or
// single-sided, whose fragments may be discarded) each with a program of
// their own, so opaque ones keep early depth testing; and for a point
// light's faces, whose fragments write their radial depth, a pair more.
#include "penumbra/gl/program.hpp"
#include "render/gpu_scene.hpp"

namespace penumbra {

class SceneShadowCasters {
 public:
  SceneShadowCasters();

  // Draws the scene from shadow view `view` of the shadow-views block
  // (which must be bound); `radial`: the view's fragments write their
  // depth (CasterDepth::Written); `samples`: the layer's samples per texel
  // (ShadowSettings::shadow_msaa).
  void draw(const GpuScene& scene, int view, bool radial, int samples = 1) const;
  // The same view's second surfaces (ShadowMapPass::execute()'s
  // draw_second): the programs that discard what lies at or in front of
  // the view's first layer; `radial` as for draw().
  void draw_second_surfaces(const GpuScene& scene, int view, bool radial);

 private:
  static void draw_with(const gl::Program (&programs)[2], const GpuScene& scene, int view,
                        int samples);

  // [radial][cut-outs]: opaque surfaces, then alpha-tested and
  // single-sided ones.
  gl::Program programs_[2][2];
  gl::Program second_programs_[2][2];  // [radial][cut-outs], SECOND_SURFACES 1, made on first use
};

}  // namespace penumbra
