// Renderer::render() reuses the G-buffer and the ambient occlusion of the
// last frame when the camera and the image size are the same (and the
// SSAO settings, for the AO); anything else draws them anew. Each frame
// here must equal the same frame from a fresh renderer.
#include <gtest/gtest.h>

#include <optional>

#include "gpu_fixture.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "render/renderer.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

RenderSettings frame(View v, int width = 96, int height = 64) {
  RenderSettings rs;
  rs.width = width;
  rs.height = height;
  rs.view = v;
  return rs;
}

ShadowSettings small_maps() {
  ShadowSettings shadow;
  shadow.technique = Technique::Pcf;
  shadow.map_size = 256;
  return shadow;
}

Camera moved_camera(const Scene& scene) {
  Camera camera = scene.camera;
  camera.position += glm::vec3(1.5f, -1.0f, 0.5f);
  return camera;
}

// The same frame from a renderer that has drawn nothing before.
Image fresh(const Camera& camera, const RenderSettings& render, const SsaoSettings& ssao = {}) {
  Renderer renderer(*builtin_scene("default"));
  renderer.set_camera(camera);
  renderer.render(render, small_maps(), ssao);
  return renderer.read_view();
}

TEST_F(GpuTest, FramesForAnotherCameraOrSizeDrawTheirOwnSurfaces) {
  const Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  renderer.render(frame(View::Final), small_maps());
  const Image first = renderer.read_view();
  renderer.render(frame(View::Final), small_maps());
  EXPECT_EQ(renderer.read_view().rgba, first.rgba) << "the same frame again";

  const Camera moved = moved_camera(scene);
  renderer.set_camera(moved);
  renderer.render(frame(View::Final), small_maps());
  const Image second = renderer.read_view();
  EXPECT_NE(second.rgba, first.rgba);
  EXPECT_EQ(second.rgba, fresh(moved, frame(View::Final)).rgba) << "another camera";

  renderer.render(frame(View::Final, 80, 48), small_maps());
  EXPECT_EQ(renderer.read_view().rgba, fresh(moved, frame(View::Final, 80, 48)).rgba)
      << "another size";

  // A map view between two frames leaves the camera's surfaces alone.
  renderer.set_camera(scene.camera);
  renderer.render(frame(View::ShadowMap), small_maps());
  renderer.render(frame(View::Final), small_maps());
  EXPECT_EQ(renderer.read_view().rgba, first.rgba) << "back to the first camera";
}

TEST_F(GpuTest, OtherSsaoSettingsComputeTheAmbientOcclusionAgain) {
  const Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  renderer.render(frame(View::Ao), small_maps());
  const Image wide = renderer.read_view();
  SsaoSettings narrow;
  narrow.radius = 0.3f;
  renderer.render(frame(View::Ao), small_maps(), narrow);
  const Image narrowed = renderer.read_view();
  EXPECT_NE(narrowed.rgba, wide.rgba);
  EXPECT_EQ(narrowed.rgba, fresh(scene.camera, frame(View::Ao), narrow).rgba);
  // A shadow view computes no AO; the lit view after it needs the AO of
  // its own settings.
  renderer.render(frame(View::Shadow), small_maps());
  renderer.render(frame(View::Final), small_maps());
  EXPECT_EQ(renderer.read_view().rgba, fresh(scene.camera, frame(View::Final)).rgba);
}

// Which of the camera's passes a timed frame drew.
struct CameraPasses {
  bool gbuffer = false, ssao = false;
};

CameraPasses timed_frame(Renderer& renderer) {
  gl::GpuProfiler profiler(1, /*serialize=*/true);
  profiler.begin_frame();
  renderer.render(frame(View::Final), small_maps(), {}, &profiler);
  profiler.end_frame();
  const std::optional<gl::GpuFrameTimes> times = profiler.read(true);
  if (!times) return {};
  return {times->ran[static_cast<std::size_t>(gl::GpuPass::GBuffer)],
          times->ran[static_cast<std::size_t>(gl::GpuPass::AmbientOcclusion)]};
}

// A timed frame that reuses the surfaces times no G-buffer or SSAO pass
// (the viewer's sub-frames of --accumulate); after forget_surfaces() it
// draws and times them (bench times every pass of every frame).
TEST_F(GpuTest, ForgettingTheSurfacesDrawsThemAgain) {
  Renderer renderer(*builtin_scene("default"));
  const CameraPasses first = timed_frame(renderer);
  EXPECT_TRUE(first.gbuffer && first.ssao);
  const CameraPasses reused = timed_frame(renderer);
  EXPECT_FALSE(reused.gbuffer || reused.ssao);
  renderer.forget_surfaces();
  const CameraPasses again = timed_frame(renderer);
  EXPECT_TRUE(again.gbuffer && again.ssao);
}

}  // namespace
}  // namespace penumbra
