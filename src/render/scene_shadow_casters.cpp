#include "render/scene_shadow_casters.hpp"

namespace penumbra {

namespace {

gl::Program caster_program(bool radial, bool cut_outs) {
  return gl::Program::graphics(
      "shadow/shadow_depth.vert", "shadow/shadow_depth.frag",
      {{"RADIAL_DEPTH", radial ? "1" : "0"}, {"CUT_OUTS", cut_outs ? "1" : "0"}});
}

}  // namespace

SceneShadowCasters::SceneShadowCasters()
    : programs_{{caster_program(false, false), caster_program(false, true)},
                {caster_program(true, false), caster_program(true, true)}} {}

void SceneShadowCasters::draw(const GpuScene& scene, int view, bool radial) const {
  const gl::Program& opaque = programs_[radial ? 1 : 0][0];
  const gl::Program& cut_out = programs_[radial ? 1 : 0][1];
  glProgramUniform1i(opaque.id(), 0, view);
  glProgramUniform1i(cut_out.id(), 0, view);
  opaque.use();
  scene.draw(SurfaceSet::Opaque);
  cut_out.use();
  scene.draw(SurfaceSet::CutOut);
}

}  // namespace penumbra
