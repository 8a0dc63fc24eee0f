// The GPU filters against CPU references: the separable Gaussian against a
// direct 2D convolution, the summed-area table's box filter against a
// double-precision box filter, its sub-texel rectangles against the exact
// integral of the texel-constant map.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <random>
#include <span>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/filter/gaussian.hpp"
#include "penumbra/filter/gaussian_blur_pass.hpp"
#include "penumbra/filter/summed_area_table_pass.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/shared/bindings.h"

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
  // Awkward sizes: not multiples of the 64 x 8 tiles; radii up to past a
  // tile. Both ways of reading the taps (a tile in shared memory, as GPUs
  // run it, and straight from the source, as CPU rasterizers do) sum the
  // same texels in the same order: the same floats.
  struct Case {
    int width, height, channels, radius;
  };
  for (const Case& k :
       {Case{37, 29, 4, 1}, Case{130, 67, 2, 5}, Case{64, 64, 1, 16}, Case{71, 200, 4, 40}}) {
    HostMap map = random_map(k.width, k.height, k.channels, 7);
    gl::Texture source = upload(map);
    std::vector<HostMap> outputs;
    for (auto staging :
         {GaussianBlurPass::Staging::SharedMemory, GaussianBlurPass::Staging::Direct}) {
      GaussianBlurPass blur(staging);
      blur.execute(source, k.radius);
      outputs.push_back(download(blur.output(), k.channels));
    }
    const HostMap& out = outputs.front();
    const std::vector<float> w = gaussian_weights(k.radius);
    double worst = 0.0;
    int differing = 0;
    for (int y = 0; y < k.height; ++y)
      for (int x = 0; x < k.width; ++x)
        for (int c = 0; c < k.channels; ++c) {
          worst = std::max(worst, std::abs(out.at(x, y, c) - gaussian_reference(map, w, x, y, c)));
          if (out.at(x, y, c) != outputs.back().at(x, y, c)) ++differing;
        }
    std::printf("gaussian %dx%d W=%d: max abs error %.2e\n", k.width, k.height, k.radius, worst);
    EXPECT_LE(worst, 1e-5) << k.width << "x" << k.height << " W=" << k.radius;
    EXPECT_EQ(differing, 0) << "values that differ between the two stagings, " << k.width << "x"
                            << k.height << " W=" << k.radius;
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

// The table's raw integers, layer by layer.
std::vector<std::uint32_t> read_table(const gl::Texture& table, int channels) {
  const GLenum layout = channels == 1   ? GL_RED_INTEGER
                        : channels == 2 ? GL_RG_INTEGER
                                        : GL_RGBA_INTEGER;
  std::vector<std::uint32_t> values(static_cast<std::size_t>(table.width()) * table.height() *
                                    table.layers() * channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(table.id(), 0, layout, GL_UNSIGNED_INT,
                    static_cast<GLsizei>(values.size() * sizeof(std::uint32_t)), values.data());
  return values;
}

// The parallel scans (tiles scanned in shared memory, a carry along each
// line) give the one-thread-per-line table bit for bit: at sizes the tiles
// do not divide (a single texel, lines shorter and longer than a tile,
// 300 x 257), with several layers, for every channel count, and for
// 16-bit moments (whose rows read RGBA16).
TEST_F(GpuTest, ParallelSummedAreaTableEqualsTheSerialOne) {
  const int sizes[][2] = {{1, 1}, {5, 37}, {33, 8}, {64, 64}, {300, 257}};
  for (const auto& size : sizes) {
    for (int channels : {1, 2, 4}) {
      std::vector<HostMap> layers;
      for (unsigned seed : {3u, 4u, 5u}) {
        layers.push_back(random_map(size[0], size[1], channels, seed + 10u * channels));
      }
      const gl::Texture source = upload(layers);
      SummedAreaTablePass parallel(SatScan::Parallel), serial(SatScan::Serial);
      parallel.execute(source);
      serial.execute(source);
      const std::vector<std::uint32_t> a = read_table(parallel.table(), channels);
      const std::vector<std::uint32_t> b = read_table(serial.table(), channels);
      ASSERT_EQ(a.size(), b.size());
      std::size_t differ = 0;
      for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];
      EXPECT_EQ(differ, 0u) << size[0] << " x " << size[1] << ", " << channels << " channels";
      EXPECT_NE(a.back(), 0u);  // the sums are there
    }
  }
  // msm16's RGBA16 moments.
  HostMap moments = random_map(130, 70, 4, 7);
  gl::Texture rgba16(gl::TextureInfo{.target = GL_TEXTURE_2D_ARRAY,
                                     .format = GL_RGBA16,
                                     .width = moments.width,
                                     .height = moments.height,
                                     .layers = 1,
                                     .label = "16-bit moments"});
  glTextureSubImage3D(rgba16.id(), 0, 0, 0, 0, moments.width, moments.height, 1, GL_RGBA, GL_FLOAT,
                      moments.values.data());
  SummedAreaTablePass parallel(SatScan::Parallel), serial(SatScan::Serial);
  parallel.execute(rgba16);
  serial.execute(rgba16);
  EXPECT_EQ(read_table(parallel.table(), 4), read_table(serial.table(), 4));
}

TEST_F(GpuTest, SummedAreaTableOf2048MapKeepsItsPrecision) {
  // The precision a float SAT loses at this size: the fixed-point one
  // does not (every 7th texel checked, all four channels).
  const double worst = worst_sat_error(2048, 2048, 4, {2, 16, 64}, 7);
  std::printf("SAT box filter 2048x2048: max abs error %.2e\n", worst);
  EXPECT_LE(worst, 4e-6);
}

// The exact average of the texel-constant map over the continuous
// rectangle [cx - hx, cx + hx] x [cy - hy, cy + hy] (texel (i, j) covers
// [i, i + 1] x [j, j + 1]), cropped to the map, its centre first clamped
// onto the map: each texel weighted by the area of it inside, by brute force.
double rectangle_integral_average(const HostMap& m, glm::dvec4 r, int c) {
  const double cx = std::clamp(r.x, 0.0, double(m.width));
  const double cy = std::clamp(r.y, 0.0, double(m.height));
  const double x0 = std::max(cx - r.z, 0.0), x1 = std::min(cx + r.z, double(m.width));
  const double y0 = std::max(cy - r.w, 0.0), y1 = std::min(cy + r.w, double(m.height));
  double sum = 0.0;
  for (int y = 0; y < m.height; ++y) {
    const double wy = std::min(y + 1.0, y1) - std::max(double(y), y0);
    if (wy <= 0.0) continue;
    for (int x = 0; x < m.width; ++x) {
      const double wx = std::min(x + 1.0, x1) - std::max(double(x), x0);
      if (wx > 0.0) sum += wx * wy * m.at(x, y, c);
    }
  }
  return sum / ((x1 - x0) * (y1 - y0));
}

// Runs shaders/test/sat_rectangle.comp on the table of layer 0.
std::vector<glm::vec4> rectangle_averages(const gl::Texture& table,
                                          const std::vector<glm::vec4>& rectangles) {
  static gl::Program program = gl::Program::compute("test/sat_rectangle.comp");
  gl::Buffer input = gl::Buffer::from(std::span<const glm::vec4>(rectangles), "rectangles");
  gl::Buffer output(rectangles.size() * sizeof(glm::vec4), nullptr, false, "averages");
  program.use();
  glProgramUniform1ui(program.id(), 0, static_cast<GLuint>(rectangles.size()));
  glProgramUniform1f(program.id(), 1, static_cast<float>(sat_fixed_point_scale()));
  glProgramUniform1i(program.id(), 2, 0);
  glBindTextureUnit(UNIT_COMPUTE_INPUT, table.id());
  glBindSampler(UNIT_COMPUTE_INPUT, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
  glDispatchCompute(static_cast<GLuint>((rectangles.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> results(rectangles.size());
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(output.size()), results.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return results;
}

// Sub-texel rectangles: random centres (some off the map), half-widths from
// a twentieth of a texel to the widest filter, square and elongated, on an
// awkward-sized map: the table's weighted boxes against the exact integral.
TEST_F(GpuTest, SatRectangleAverageMatchesTheExactIntegral) {
  const int width = 157, height = 131;
  HostMap map = random_map(width, height, 4, 23);
  gl::Texture source = upload(map);
  SummedAreaTablePass sat;
  sat.execute(source);
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<glm::vec4> rectangles;
  for (int k = 0; k < 3000; ++k) {
    const float cx = -3.0f + (width + 6.0f) * u(rng), cy = -3.0f + (height + 6.0f) * u(rng);
    // Log-uniform half-widths in [0.05, kMaxBlur + 1/2].
    auto half_width = [&] { return 0.05f * std::pow((kMaxBlur + 0.5f) / 0.05f, u(rng)); };
    const float hx = half_width();
    rectangles.emplace_back(cx, cy, hx, k % 2 ? hx : half_width());
  }
  // Every corner and edge of the map, with the centre exactly on it.
  for (float cx : {0.0f, 0.5f, float(width) - 0.25f, float(width)})
    for (float cy : {0.0f, 3.75f, float(height)}) rectangles.emplace_back(cx, cy, 2.5f, 0.7f);
  const std::vector<glm::vec4> gpu = rectangle_averages(sat.table(), rectangles);
  double worst = 0.0;
  for (std::size_t i = 0; i < rectangles.size(); ++i)
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(gpu[i][c] - rectangle_integral_average(
                                                       map, glm::dvec4(rectangles[i]), c)));
  std::printf("SAT sub-texel rectangles %dx%d: max abs error %.2e\n", width, height, worst);
  // The stored values' rounding (2^-18), and float weights and sums.
  EXPECT_LE(worst, 1e-5);
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
