#include "render/scene_shadow_casters.hpp"

namespace penumbra {

SceneShadowCasters::SceneShadowCasters()
    : program_(gl::Program::graphics("shadow/shadow_depth.vert", "shadow/shadow_depth.frag",
                                     {{"CUT_OUTS", "0"}})),
      cut_out_program_(gl::Program::graphics("shadow/shadow_depth.vert", "shadow/shadow_depth.frag",
                                             {{"CUT_OUTS", "1"}})) {}

void SceneShadowCasters::draw(const GpuScene& scene, int view) const {
  glProgramUniform1i(program_.id(), 0, view);
  glProgramUniform1i(cut_out_program_.id(), 0, view);
  program_.use();
  scene.draw(SurfaceSet::Opaque);
  cut_out_program_.use();
  scene.draw(SurfaceSet::CutOut);
}

}  // namespace penumbra
