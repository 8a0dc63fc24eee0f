// The GPU filters against CPU references: the separable Gaussian against a
// direct 2D convolution, the summed-area table's box filter against a
// double-precision box filter.
#include <cmath>
#include <random>
#include <vector>

#include "filter/gaussian.hpp"
#include "filter/gaussian_blur_pass.hpp"
#include "filter/summed_area_table_pass.hpp"
#include "gpu_fixture.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

struct HostMap {
  int width, height, channels;
  std::vector<float> values;  // row-major, `channels` per texel
  [[nodiscard]] float at(int x, int y, int c) const {
    return values[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
};

// A map with smooth regions and sharp edges, like a moment map.
HostMap random_map(int width, int height, int channels, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  HostMap m{width, height, channels, {}};
  m.values.resize(static_cast<std::size_t>(width) * height * channels);
  const float cx = u(rng) * width, cy = u(rng) * height, r = 0.3f * std::min(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool inside = std::hypot(x - cx, y - cy) < r;
      const float z = inside ? 0.2f + 0.05f * u(rng) : 0.6f + 0.4f * float(y) / height;
      for (int c = 0; c < channels; ++c) {
        m.values[(static_cast<std::size_t>(y) * width + x) * channels + c] =
            std::pow(z, float(c + 1));
      }
    }
  }
  return m;
}

GLenum float_format(int channels) {
  return channels == 1 ? GL_R32F : channels == 2 ? GL_RG32F : GL_RGBA32F;
}

// The maps as the layers of a 2D array (the filters work on arrays, one
// layer per shadow view); all the same size and channel count.
gl::Texture upload(const std::vector<HostMap>& maps) {
  const HostMap& m = maps.front();
  gl::Texture t(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                .format = float_format(m.channels),
                                .width = m.width,
                                .height = m.height,
                                .layers = static_cast<int>(maps.size()),
                                .label = "test maps"});
  const GLenum layout = m.channels == 1 ? GL_RED : m.channels == 2 ? GL_RG : GL_RGBA;
  for (std::size_t layer = 0; layer < maps.size(); ++layer) {
    glTextureSubImage3D(t.id(), 0, 0, 0, static_cast<GLint>(layer), m.width, m.height, 1, layout,
                        GL_FLOAT, maps[layer].values.data());
  }
  return t;
}

gl::Texture upload(const HostMap& m) {
  return upload(std::vector<HostMap>{m});
}

HostMap download(const gl::Texture& t, int channels, int layer = 0) {
  HostMap m{t.width(), t.height(), channels, {}};
  m.values.resize(static_cast<std::size_t>(t.width()) * t.height() * channels);
  const GLenum layout = channels == 1 ? GL_RED : channels == 2 ? GL_RG : GL_RGBA;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureSubImage(t.id(), 0, 0, 0, layer, t.width(), t.height(), 1, layout, GL_FLOAT,
                       static_cast<GLsizei>(m.values.size() * 4), m.values.data());
  return m;
}

// Direct (non-separable) convolution with clamp-to-border, in double.
double gaussian_reference(const HostMap& m, const std::vector<float>& w, int x, int y, int c) {
  const int r = static_cast<int>(w.size() / 2);
  double sum = 0.0;
  for (int j = -r; j <= r; ++j) {
    for (int i = -r; i <= r; ++i) {
      const int sx = std::clamp(x + i, 0, m.width - 1), sy = std::clamp(y + j, 0, m.height - 1);
      sum += double(w[static_cast<std::size_t>(i + r)]) * w[static_cast<std::size_t>(j + r)] *
             m.at(sx, sy, c);
    }
  }
  return sum;
}

TEST_F(GpuTest, GaussianBlurMatchesDirectConvolution) {
  // Awkward sizes: not multiples of the 64 x 8 tiles; radii up to past a tile.
  struct Case {
    int width, height, channels, radius;
  };
  for (const Case& k :
       {Case{37, 29, 4, 1}, Case{130, 67, 2, 5}, Case{64, 64, 1, 16}, Case{71, 200, 4, 40}}) {
    HostMap map = random_map(k.width, k.height, k.channels, 7);
    gl::Texture source = upload(map);
    GaussianBlurPass blur;
    blur.execute(source, k.radius);
    HostMap out = download(blur.output(), k.channels);
    const std::vector<float> w = gaussian_weights(k.radius);
    double worst = 0.0;
    for (int y = 0; y < k.height; ++y)
      for (int x = 0; x < k.width; ++x)
        for (int c = 0; c < k.channels; ++c)
          worst = std::max(worst, std::abs(out.at(x, y, c) - gaussian_reference(map, w, x, y, c)));
    std::printf("gaussian %dx%d W=%d: max abs error %.2e\n", k.width, k.height, k.radius, worst);
    EXPECT_LE(worst, 1e-5) << k.width << "x" << k.height << " W=" << k.radius;
  }
}

// The box average of a cropped box, from a double-precision SAT.
struct ReferenceSat {
  int width, height, channels;
  std::vector<double> sums;  // (width + 1) x (height + 1), zero first row and column
  explicit ReferenceSat(const HostMap& m)
      : width(m.width),
        height(m.height),
        channels(m.channels),
        sums(static_cast<std::size_t>(m.width + 1) * (m.height + 1) * m.channels, 0.0) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < channels; ++c)
          at(x + 1, y + 1, c) = m.at(x, y, c) + at(x, y + 1, c) + at(x + 1, y, c) - at(x, y, c);
  }
  double& at(int x, int y, int c) {
    return sums[(static_cast<std::size_t>(y) * (width + 1) + x) * channels + c];
  }
  double box(int x, int y, int r, int c) {
    const int x0 = std::max(x - r, 0), y0 = std::max(y - r, 0);
    const int x1 = std::min(x + r, width - 1) + 1, y1 = std::min(y + r, height - 1) + 1;
    const double s = at(x1, y1, c) - at(x0, y1, c) - at(x1, y0, c) + at(x0, y0, c);
    return s / (double(x1 - x0) * (y1 - y0));
  }
};

double worst_sat_error(int width, int height, int channels, const std::vector<int>& radii,
                       int stride) {
  HostMap map = random_map(width, height, channels, 11);
  gl::Texture source = upload(map);
  SummedAreaTablePass sat;
  sat.execute(source);
  ReferenceSat reference(map);
  double worst = 0.0;
  for (int radius : radii) {
    HostMap out = download(sat.box_filtered(radius), 4);
    for (int y = 0; y < height; y += stride)
      for (int x = 0; x < width; x += stride)
        for (int c = 0; c < channels; ++c)
          worst = std::max(worst, std::abs(out.at(x, y, c) - reference.box(x, y, radius, c)));
  }
  return worst;
}

TEST_F(GpuTest, SummedAreaTableBoxFilterMatchesDoubleReference) {
  // Awkward sizes and radii, every texel checked (near the border too).
  const double small = worst_sat_error(37, 29, 4, {0, 1, 3, 20}, 1);
  const double odd = worst_sat_error(300, 257, 2, {2, 32, 64}, 1);
  std::printf("SAT box filter 37x29 / 300x257: max abs error %.2e / %.2e\n", small, odd);
  // Each value is stored to within 2^-18 (fixed point 2^17): the average of
  // rounded values is within that of the true average.
  EXPECT_LE(small, 4e-6);
  EXPECT_LE(odd, 4e-6);
}

TEST_F(GpuTest, SummedAreaTableOf2048MapKeepsItsPrecision) {
  // The precision a float SAT loses at this size: the fixed-point one
  // does not (every 7th texel checked, all four channels).
  const double worst = worst_sat_error(2048, 2048, 4, {2, 16, 64}, 7);
  std::printf("SAT box filter 2048x2048: max abs error %.2e\n", worst);
  EXPECT_LE(worst, 4e-6);
}

TEST_F(GpuTest, FiltersKeepArrayLayersApart) {
  // Three different maps as the layers of one array (as a point light's
  // cube faces are): each layer's result is that of its map alone, nothing
  // mixed in from the neighbouring layers.
  const int width = 45, height = 38, radius = 6;
  std::vector<HostMap> maps;
  for (unsigned seed : {3u, 5u, 9u}) maps.push_back(random_map(width, height, 4, seed));
  gl::Texture layered = upload(maps);
  GaussianBlurPass blur;
  blur.execute(layered, radius);
  SummedAreaTablePass sat;
  sat.execute(layered);
  const std::vector<float> w = gaussian_weights(radius);
  for (int layer = 0; layer < 3; ++layer) {
    const HostMap& map = maps[static_cast<std::size_t>(layer)];
    HostMap blurred = download(blur.output(), 4, layer);
    ReferenceSat reference(map);
    HostMap boxed = download(sat.box_filtered(radius), 4, layer);
    double blur_error = 0.0, box_error = 0.0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 4; ++c) {
          blur_error = std::max(
              blur_error, std::abs(blurred.at(x, y, c) - gaussian_reference(map, w, x, y, c)));
          box_error =
              std::max(box_error, std::abs(boxed.at(x, y, c) - reference.box(x, y, radius, c)));
        }
    EXPECT_LE(blur_error, 1e-5) << "layer " << layer;
    EXPECT_LE(box_error, 4e-6) << "layer " << layer;
  }
}

}  // namespace
}  // namespace penumbra
