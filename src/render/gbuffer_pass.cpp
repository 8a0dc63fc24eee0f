#include "render/gbuffer_pass.hpp"

#include "render/camera_depth.hpp"

namespace penumbra {

GBufferPass::GBufferPass()
    : program_(
          gl::Program::graphics("scene/gbuffer.vert", "scene/gbuffer.frag", {{"CUT_OUTS", "0"}})),
      cut_out_program_(
          gl::Program::graphics("scene/gbuffer.vert", "scene/gbuffer.frag", {{"CUT_OUTS", "1"}})) {}

void GBufferPass::execute(const GpuScene& scene, int width, int height) {
  if (width != width_ || height != height_) {
    auto make = [&](GLenum format, const char* label) {
      return gl::Texture(
          gl::TextureInfo{.format = format, .width = width, .height = height, .label = label});
    };
    depth_ = make(GL_DEPTH_COMPONENT32F, "gbuffer depth");
    normal_ = make(GL_RGBA16F, "gbuffer normal");
    albedo_ = make(GL_SRGB8_ALPHA8, "gbuffer albedo");
    specular_ = make(GL_RGBA8, "gbuffer specular");
    // Half floats: the rise is kept to its own 11 bits at any scene scale.
    facet_ = make(GL_RGBA16F, "gbuffer facet");
    framebuffer_ = gl::Framebuffer("gbuffer");
    framebuffer_.attach_depth(depth_);
    framebuffer_.attach_color(0, normal_);
    framebuffer_.attach_color(1, albedo_);
    framebuffer_.attach_color(2, specular_);
    framebuffer_.attach_color(3, facet_);
    framebuffer_.set_draw_buffers(4);
    framebuffer_.check_complete();
    width_ = width;
    height_ = height;
  }

  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "gbuffer");
  const GLuint fb = framebuffer_.id();
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glViewport(0, 0, width, height);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const auto far_depth = static_cast<float>(CAMERA_FAR_DEPTH);
  for (int i = 0; i < 4; ++i) glClearNamedFramebufferfv(fb, GL_COLOR, i, zero);
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
  // Reversed-Z (render/camera_depth.hpp): window depth = NDC z in [0, 1],
  // nearer is greater. The clip control is put back below, so passes that
  // follow (and an engine's own state, for tests sharing a context) see
  // the one they had.
  GLint clip_origin = GL_LOWER_LEFT, clip_depth = GL_NEGATIVE_ONE_TO_ONE;
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_origin);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  // The albedo target is sRGB8: with GL_FRAMEBUFFER_SRGB on, the linear
  // albedo the shader writes is encoded on the way in, and sampling decodes
  // it back (OpenGL 4.5, section 17.3.7). Off, the linear value would be
  // stored as if encoded and read back as albedo^2.2.
  glEnable(GL_FRAMEBUFFER_SRGB);
  program_.use();
  scene.draw(SurfaceSet::Opaque, GpuScene::Corners::Read);
  cut_out_program_.use();
  scene.draw(SurfaceSet::CutOut, GpuScene::Corners::Read);
  glDisable(GL_FRAMEBUFFER_SRGB);
  glDepthFunc(GL_LESS);
  glClipControl(static_cast<GLenum>(clip_origin), static_cast<GLenum>(clip_depth));
  glPopDebugGroup();
}

}  // namespace penumbra
