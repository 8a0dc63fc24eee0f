// The viewer's window shows what `penumbra render` writes: the present pass
// encodes each view as the PNG writer does.
#include "render/present_pass.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gpu_fixture.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

TEST(FitRect, KeepsTheAspectRatioCentred) {
  EXPECT_EQ(fit_rect(320, 240, {0, 0, 320, 240}), (PixelRect{0, 0, 320, 240}));
  EXPECT_EQ(fit_rect(512, 512, {0, 0, 400, 200}), (PixelRect{100, 0, 200, 200}));
  EXPECT_EQ(fit_rect(512, 512, {10, 20, 200, 400}), (PixelRect{10, 120, 200, 200}));
  EXPECT_EQ(fit_rect(640, 480, {0, 0, 0, 480}).width, 0);
}

// What the window shows for the view just rendered, read back as an image.
Image presented(Renderer& renderer) {
  const ViewSource source = renderer.view_source();
  const int w = source.texture->width(), h = source.texture->height();
  gl::Texture target(
      gl::TextureInfo{.format = GL_RGBA8, .width = w, .height = h, .label = "presented"});
  gl::Framebuffer framebuffer("present test");
  framebuffer.attach_color(0, target);
  framebuffer.set_draw_buffers(1);
  framebuffer.check_complete();
  PresentPass present;
  present.execute(source, framebuffer.id(), {0, 0, w, h});
  Image image(w, h);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(target.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bytes.size()),
                    bytes.data());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = &bytes[(static_cast<std::size_t>(h - 1 - y) * w + x) * 4];
      for (int c = 0; c < 4; ++c) image.pixel(x, y)[c] = p[c] / 255.0f;
    }
  }
  return image;
}

// read_view() as `penumbra render` writes it to PNG, read back.
Image written(Renderer& renderer, View view) {
  const auto path = std::filesystem::path(PENUMBRA_TEST_OUTPUT) / "present_reference.png";
  std::filesystem::create_directories(path.parent_path());
  write_png(renderer.read_view(), path.string(),
            view == View::Final ? PngEncoding::Srgb : PngEncoding::Linear);
  return read_png(path.string());
}

class PresentPassTest : public GpuTest {};

TEST_F(PresentPassTest, ShowsEveryViewAsRenderWritesIt) {
  Scene scene = *builtin_scene("default");
  Renderer renderer(scene);
  struct Case {
    Technique technique;
    View view;
  };
  const Case cases[] = {
      {Technique::Pcf, View::Final},          {Technique::Hard, View::Shadow},
      {Technique::Hard, View::ShadowMap},     {Technique::Vsm, View::Moments},
      {Technique::Esm, View::Moments},        {Technique::Esm, View::MomentsFiltered},
      {Technique::Msm, View::Normals},        {Technique::Msm16, View::Albedo},
      {Technique::Msm, View::MomentsFiltered}};
  for (const Case& c : cases) {
    RenderSettings render;
    render.width = 96;
    render.height = 64;
    render.view = c.view;
    ShadowSettings shadow;
    shadow.technique = c.technique;
    shadow.map_size = 128;
    renderer.render(render, shadow);
    const Image expected = written(renderer, c.view);
    const Image shown = presented(renderer);
    SCOPED_TRACE(std::string(enum_name<View>(kViewNames, c.view)) + " of " +
                 std::string(enum_name<Technique>(kTechniqueNames, c.technique)));
    ASSERT_EQ(shown.width, expected.width);
    ASSERT_EQ(shown.height, expected.height);
    float worst = 0.0f;
    for (int y = 0; y < shown.height; ++y) {
      for (int x = 0; x < shown.width; ++x) {
        for (int ch = 0; ch < 3; ++ch) {
          worst = std::max(worst, std::abs(shown.pixel(x, y)[ch] - expected.pixel(x, y)[ch]));
        }
      }
    }
    // One 8-bit step: the GPU's pow and rounding against the CPU's.
    EXPECT_LE(worst, 1.0f / 255.0f + 1e-6f);
  }
}

}  // namespace
}  // namespace penumbra
