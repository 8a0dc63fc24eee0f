// Mipmapped filtered maps (--shadow-mips): the chain MipChainPass makes
// is the 2x2 mean of each level below, for every representation format,
// odd sizes and several layers, and in the renderer's own maps; and on a
// long ground plane under a sun, reading the chain over each pixel's
// footprint brings the shadow closer to the pixel's true (area-averaged)
// shadow than the single-level lookup, whose far stripes alias.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/filter/mip_chain_pass.hpp"
#include "penumbra/shadow/representation.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

GLenum pixel_format_of(int channels) {
  return channels == 1 ? GL_RED : channels == 2 ? GL_RG : GL_RGBA;
}

// Every layer of one level, as floats (`channels` per texel).
std::vector<float> read_level(const gl::Texture& t, int level, int width, int height,
                              int channels) {
  std::vector<float> data(static_cast<std::size_t>(width) * height * t.layers() * channels);
  glGetTextureImage(t.id(), level, pixel_format_of(channels), GL_FLOAT,
                    static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  return data;
}

// Checks that each level of `t` is the mean of the 2x2 texels it covers in
// the level below, within `tolerance` (times the largest of the four where
// that exceeds 1), and returns how many levels it has.
int expect_box_chain(const gl::Texture& t, double tolerance) {
  const int channels = channel_count(t.format());
  int w = t.width(), h = t.height();
  std::vector<float> finer = read_level(t, 0, w, h, channels);
  for (int level = 1; level < t.levels(); ++level) {
    const int cw = std::max(w / 2, 1), ch = std::max(h / 2, 1);
    const std::vector<float> coarser = read_level(t, level, cw, ch, channels);
    double worst = 0.0;
    for (int layer = 0; layer < t.layers(); ++layer) {
      for (int y = 0; y < ch; ++y) {
        for (int x = 0; x < cw; ++x) {
          for (int c = 0; c < channels; ++c) {
            double sum = 0.0, magnitude = 0.0;
            for (int dy = 0; dy < 2; ++dy) {
              for (int dx = 0; dx < 2; ++dx) {
                const int fx = std::min(2 * x + dx, w - 1), fy = std::min(2 * y + dy, h - 1);
                const double v =
                    finer[((static_cast<std::size_t>(layer) * h + fy) * w + fx) * channels + c];
                sum += v;
                magnitude = std::max(magnitude, std::abs(v));
              }
            }
            const double got =
                coarser[((static_cast<std::size_t>(layer) * ch + y) * cw + x) * channels + c];
            // Relative to the values' size: EVSM's warps span dozens of
            // orders of magnitude.
            worst = std::max(worst, std::abs(got - 0.25 * sum) / std::max(magnitude, 1.0));
          }
        }
      }
    }
    EXPECT_LE(worst, tolerance) << "level " << level << " of " << format_name(t.format());
    finer = coarser;
    w = cw;
    h = ch;
  }
  return t.levels();
}

class ShadowMipsTest : public GpuTest {};

TEST_F(ShadowMipsTest, EachLevelIsTheMeanOfTheTwoByTwoTexelsBelow) {
  // Odd and even sizes (the odd ones drop their last row or column, as
  // OpenGL's chain does) and three layers, in every representation format.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  MipChainPass pass;
  for (const GLenum format : {GL_R32F, GL_RG32F, GL_RGBA32F, GL_RGBA16}) {
    for (const auto& [width, height] : {std::pair{37, 20}, std::pair{64, 64}}) {
      const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(width, height))));
      gl::Texture t(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                    .format = format,
                                    .width = width,
                                    .height = height,
                                    .layers = 3,
                                    .levels = levels,
                                    .label = "test mip chain"});
      const int channels = channel_count(format);
      std::vector<float> data(static_cast<std::size_t>(width) * height * 3 * channels);
      for (float& v : data) v = u(rng);
      glTextureSubImage3D(t.id(), 0, 0, 0, 0, width, height, 3, pixel_format_of(channels), GL_FLOAT,
                          data.data());
      pass.execute(t);
      // Float: the mean of four floats, rounded once or twice. RGBA16: the
      // mean of four 16-bit values rounded to 16 bits (half a step) plus
      // the float arithmetic before it.
      const double tolerance = format == GL_RGBA16 ? 0.5 / 65535.0 + 1e-6 : 1e-6;
      EXPECT_EQ(expect_box_chain(t, tolerance), levels);
    }
  }
}

// A long ground plane under slats (a pergola 240 m long), lit by a sun
// almost overhead: a ground of shadow stripes 2 m apart that recede to the
// horizon, where many stripes fall in one pixel.
Scene pergola_scene() {
  testing::TestScene scene("pergola");
  scene.ground(40.0f, 260.0f, {0.0f, 0.0f, -100.0f});
  for (float z = 24.0f; z > -224.0f; z -= 2.0f) scene.box({0.0f, 6.0f, z}, {40.0f, 0.2f, 0.5f});
  Light sun = testing::sun_light({0.3f, -1.0f, -0.2f});
  sun.intensity = 2.5f;
  return scene.camera({0.0f, 2.5f, 24.0f}, {0.0f, 0.6f, -20.0f}, 40.0f).light(sun);
}

TEST_F(ShadowMipsTest, TheRenderersMapsCarryTheChainOfTheirMoments) {
  Renderer renderer(pergola_scene());
  RenderSettings rs = testing::small_frame(64, 36);
  for (const Technique technique : {Technique::Msm, Technique::Msm16, Technique::Evsm2}) {
    for (const bool fused : {true, false}) {
      ShadowSettings shadow;
      shadow.technique = technique;
      shadow.map_size = 96;
      shadow.fused = fused;
      shadow.shadow_mips = true;
      renderer.render(rs, shadow);
      const gl::Texture& maps = renderer.shadow_maps();
      if (fused) {
        ASSERT_EQ(maps.levels(), 7);  // 96 .. 1
        EXPECT_EQ(expect_box_chain(
                      maps, technique == Technique::Msm16 ? 0.5 / 65535.0 + 1e-6 : 1e-6 * 4.0),
                  7);
      }
    }
    ShadowSettings off;
    off.technique = technique;
    off.map_size = 96;
    renderer.render(rs, off);
    EXPECT_EQ(renderer.shadow_maps().levels(), 1);
  }
}

// The traced shadow of the ground averaged over each pixel's area: traced
// at `factor` times the resolution, each pixel the mean of its factor^2
// sub-pixels; alpha 1 where every sub-pixel sees the ground (the slats
// themselves alias as geometry, which no shadow filter changes), and the
// pixel's mean distance along -z from the camera in green.
Image ground_reference(Renderer& renderer, RenderSettings rs, const ShadowSettings& shadow,
                       int factor) {
  RenderSettings fine = rs;
  fine.width *= factor;
  fine.height *= factor;
  renderer.render(fine, shadow);
  const Image traced = traced_reference(renderer, fine, shadow, 16, "").image;
  const SurfacePoints surfaces = renderer.read_surfaces();
  const float camera_z = renderer.scene().camera.position.z;
  Image averaged(rs.width, rs.height);
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      double sum = 0.0, distance = 0.0;
      int ground = 0;
      for (int sy = 0; sy < factor; ++sy) {
        for (int sx = 0; sx < factor; ++sx) {
          const int fx = x * factor + sx, fy = y * factor + sy;
          const std::size_t i = static_cast<std::size_t>(fy) * fine.width + fx;
          const float* p = traced.pixel(fx, fy);
          if (p[3] == 0.0f || !surfaces.covered[i] || std::abs(surfaces.position[i].y) > 1e-3f) {
            continue;
          }
          sum += p[0];
          distance += camera_z - surfaces.position[i].z;
          ++ground;
        }
      }
      float* out = averaged.pixel(x, y);
      out[0] = static_cast<float>(sum / std::max(ground, 1));
      out[1] = static_cast<float>(distance / std::max(ground, 1));
      out[3] = ground == factor * factor ? 1.0f : 0.0f;
    }
  }
  return averaged;
}

// RMSE of the shadow view against the reference over its ground pixels at
// least `distance` from the camera.
double rmse(const Image& image, const Image& reference, float distance) {
  double sum = 0.0;
  long n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float* r = reference.pixel(x, y);
      if (r[3] == 0.0f || r[1] < distance) continue;
      const double d = image.pixel(x, y)[0] - r[0];
      sum += d * d;
      ++n;
    }
  }
  EXPECT_GT(n, 100);
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

TEST_F(ShadowMipsTest, MipsBringTheFarGroundCloserToItsAreaAveragedShadow) {
  Renderer renderer(pergola_scene());
  RenderSettings rs = testing::small_frame(160, 90);
  ShadowSettings base;
  base.map_size = 512;
  const Image reference = ground_reference(renderer, rs, base, 4);
  for (const Technique technique : {Technique::Vsm, Technique::Msm16, Technique::Evsm4}) {
    const std::string_view name = enum_name<Technique>(kTechniqueNames, technique);
    // Without mips, then trilinear only, then anisotropic (trilinear too
    // on llvmpipe, see LightingPass).
    double error[3][2];
    for (int run = 0; run < 3; ++run) {
      ShadowSettings shadow = base;
      shadow.technique = technique;
      shadow.shadow_mips = run > 0;
      shadow.shadow_anisotropy = run == 2 ? 16 : 1;
      renderer.render(rs, shadow);
      const Image image = renderer.read_view();
      error[run][0] = rmse(image, reference, 40.0f);
      error[run][1] = rmse(image, reference, 0.0f);
    }
    std::printf(
        "%s ground RMSE against its area-averaged shadow, no mips / trilinear / "
        "anisotropic 16: beyond 40 m %.4f / %.4f / %.4f, all %.4f / %.4f / %.4f\n",
        std::string(name).c_str(), error[0][0], error[1][0], error[2][0], error[0][1], error[1][1],
        error[2][1]);
    for (int run = 1; run < 3; ++run) {
      EXPECT_LT(error[run][0], 0.75 * error[0][0]) << name << " run " << run;
      EXPECT_LT(error[run][1], error[0][1]) << name << " run " << run;
    }
  }
}

}  // namespace
}  // namespace penumbra
