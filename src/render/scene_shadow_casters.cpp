#include "render/scene_shadow_casters.hpp"

namespace penumbra {

namespace {

gl::Program caster_program(bool radial, bool cut_outs, bool second = false) {
  return gl::Program::graphics("shadow/shadow_depth.vert", "shadow/shadow_depth.frag",
                               {{"RADIAL_DEPTH", radial ? "1" : "0"},
                                {"CUT_OUTS", cut_outs ? "1" : "0"},
                                {"SECOND_SURFACES", second ? "1" : "0"}});
}

}  // namespace

SceneShadowCasters::SceneShadowCasters()
    : programs_{{caster_program(false, false), caster_program(false, true)},
                {caster_program(true, false), caster_program(true, true)}} {}

void SceneShadowCasters::draw_second_surfaces(const GpuScene& scene, int view, bool radial) {
  // Made on first use: only backprojection draws them.
  gl::Program(&programs)[2] = second_programs_[radial ? 1 : 0];
  if (!programs[0]) {
    for (int c = 0; c < 2; ++c) programs[c] = caster_program(radial, c == 1, true);
  }
  draw_with(programs, scene, view, 1);
}

void SceneShadowCasters::draw(const GpuScene& scene, int view, bool radial, int samples) const {
  draw_with(programs_[radial ? 1 : 0], scene, view, samples);
}

void SceneShadowCasters::draw_with(const gl::Program (&programs)[2], const GpuScene& scene,
                                   int view, int samples) {
  const gl::Program& opaque = programs[0];
  const gl::Program& cut_out = programs[1];
  glProgramUniform1i(opaque.id(), 0, view);
  glProgramUniform1i(cut_out.id(), 0, view);
  opaque.use();
  scene.draw(SurfaceSet::Opaque);
  cut_out.use();
  // Multisampled maps: the cut-outs' alpha test runs once per sample, at
  // the sample's own texture coordinate (sample shading, min rate 1), so
  // a leaf's outline is resolved within the texel as a triangle's edge is.
  // Alpha to coverage would do it once per texel, but it needs a colour
  // buffer, which depth-only shadow passes do not have (GL 4.5, 17.3.3).
  if (samples > 1) {
    glEnable(GL_SAMPLE_SHADING);
    glMinSampleShading(1.0f);
  }
  scene.draw(SurfaceSet::CutOut);
  if (samples > 1) glDisable(GL_SAMPLE_SHADING);
}

}  // namespace penumbra
