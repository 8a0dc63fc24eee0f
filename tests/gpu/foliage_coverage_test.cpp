// Alpha-tested foliage keeps its coverage at every distance and shadow-map
// size: a texture of small leaves (about 30 % of its texels solid, in
// blobs a few texels wide) on many small cards. Box-filtered mips average
// such alpha under the cutoff, and the leaves thin out in small maps and
// far away; the coverage-preserving chain (scene/coverage_mips.hpp), read
// by the alpha test one level at a time (shaders/scene/surface.glsl),
// keeps level 0's fraction at every level.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "gltf_files.hpp"
#include "gpu_fixture.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "scene/coverage_mips.hpp"
#include "scene/gltf_scene.hpp"

namespace penumbra {
namespace {

using testing::GltfQuad;
using testing::GltfSpec;
using testing::GpuTest;

constexpr int kLeafSide = 128;

// Leaves: discs of radius 2.2 texels at pseudo-random centres, wrapping
// around the edges (the texture repeats on the cards).
std::vector<std::uint8_t> leaf_texture() {
  std::vector<std::uint8_t> rgba(4 * kLeafSide * kLeafSide);
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    rgba[i] = 40;
    rgba[i + 1] = 160;
    rgba[i + 2] = 40;
  }
  std::uint32_t state = 12345u;
  const auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24);
  };
  const float r = 2.2f;
  for (int leaf = 0; leaf < 380; ++leaf) {
    const float cx = next() * kLeafSide, cy = next() * kLeafSide;
    for (int dy = -3; dy <= 3; ++dy) {
      for (int dx = -3; dx <= 3; ++dx) {
        const int x = static_cast<int>(std::floor(cx)) + dx;
        const int y = static_cast<int>(std::floor(cy)) + dy;
        const float ox = static_cast<float>(x) + 0.5f - cx, oy = static_cast<float>(y) + 0.5f - cy;
        if (ox * ox + oy * oy > r * r) continue;
        const int wx = (x + kLeafSide) % kLeafSide, wy = (y + kLeafSide) % kLeafSide;
        rgba[4 * (static_cast<std::size_t>(wy) * kLeafSide + wx) + 3] = 255;
      }
    }
  }
  return rgba;
}

double level0_coverage(const std::vector<std::uint8_t>& rgba) {
  return alpha_coverage(MipLevel{kLeafSide, kLeafSide, rgba}, 0.5f);
}

// The leaf material: double-sided, MASK at 0.5, the texture repeated
// `tiles` times across a card.
testing::GltfMaterialSpec leaf_material(int tiles) {
  return {.image = "leaves128.png",
          .alpha_mode = "MASK",
          .double_sided = true,
          .texture_transform =
              "{\"scale\": [" + std::to_string(tiles) + ", " + std::to_string(tiles) + "]}"};
}

// A square of side 2 * half centred on c in the plane spanned by a and b.
GltfQuad square(glm::vec3 c, glm::vec3 a, glm::vec3 b, float half, int material) {
  return {{c - half * a - half * b, c + half * a - half * b, c + half * a + half * b,
           c - half * a + half * b},
          material};
}

constexpr int kImage = 256;

RenderSettings view_settings(View view) {
  RenderSettings rs;
  rs.width = kImage;
  rs.height = kImage;
  rs.view = view;
  return rs;
}

Image render_view(Renderer& renderer, View view, const ShadowSettings& shadow) {
  renderer.render(view_settings(view), shadow);
  return renderer.read_view();
}

// Whether an albedo pixel is a leaf (green) rather than grey ground.
bool is_leaf(const float* albedo) {
  return albedo[1] > 3.0f * albedo[0];
}

// Ground pixels (grey albedo, judged by the reference) whose shadow factor
// is under one half.
long shadowed_ground(const Image& factor, const Image& albedo, const Image& judged) {
  long n = 0;
  for (int y = 0; y < kImage; ++y) {
    for (int x = 0; x < kImage; ++x) {
      if (judged.pixel(x, y)[3] < 0.5f || is_leaf(albedo.pixel(x, y))) continue;
      n += factor.pixel(x, y)[0] < 0.5f;
    }
  }
  return n;
}

// Thirty horizontal leaf cards (0.8 wide, the texture three times across)
// at heights 1 to 2 over a grey ground, under a point-like spot light
// 8 units up: a leaf is 1 to 5 shadow-map texels at 512² to 4096² maps.
// The ground's shadow area in the hard shadow, against the traced
// reference's, is within 10 % at 512² and 3 % from 1024² up.
TEST_F(GpuTest, LeafCardsCastTheirWholeShadowAtEveryMapSize) {
  testing::write_rgba_png("leaves128.png", kLeafSide, kLeafSide, leaf_texture());
  GltfSpec spec;
  spec.materials.push_back({.base_color = {0.6f, 0.6f, 0.6f, 1.0f}});
  spec.materials.push_back(leaf_material(3));
  spec.quads.push_back(square({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 6.0f, 0));
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 6; ++j) {
      const float height = 1.0f + 0.2f * static_cast<float>((i * 7 + j * 3) % 6);
      const glm::vec3 c{-2.4f + 1.2f * i, height, -3.0f + 1.2f * j};
      spec.quads.push_back(square(c, {0, 0, 1}, {1, 0, 0}, 0.4f, 1));
    }
  }
  spec.cameras.push_back({.position = {0, 7.5f, 7.5f}, .target = {0, 0, -0.3f}, .yfov = 0.9f});
  spec.lights.push_back({.type = "spot",
                         .intensity = 60.0f,
                         .inner_cone = 0.6f,
                         .outer_cone = 0.7f,
                         .position = {0.2f, 8.0f, 0.1f},
                         .direction = {0, -1, 0}});
  Renderer renderer(gltf_scene(testing::write_gltf("leaf-cards.gltf", spec)));
  ShadowSettings hard;
  hard.technique = Technique::Hard;
  hard.light_size = 0.0f;
  const Image albedo = render_view(renderer, View::Albedo, hard);
  const TracedReference traced =
      traced_reference(renderer, view_settings(View::Shadow), hard, 1, "");
  const long reference = shadowed_ground(traced.image, albedo, traced.image);
  std::printf("traced reference: %ld shadowed ground pixels\n", reference);
  ASSERT_GT(reference, 2000);
  for (const int size : {512, 1024, 2048, 4096}) {
    hard.map_size = size;
    const long area =
        shadowed_ground(render_view(renderer, View::Shadow, hard), albedo, traced.image);
    const double ratio = static_cast<double>(area) / static_cast<double>(reference);
    std::printf("hard %d²: %ld shadowed ground pixels, %.3f of the reference's\n", size, area,
                ratio);
    EXPECT_NEAR(ratio, 1.0, size >= 1024 ? 0.03 : 0.10) << size;
  }
}

// A wall of leaves facing the camera, the texture eight times across:
// near, a texel covers several pixels (level 0, magnified); at 10 units
// about five texels are a pixel, at 40 about twenty. The fraction of the
// wall's pixels that are leaves stays within 10 % of level 0's coverage.
TEST_F(GpuTest, LeafWallKeepsItsCoverageWithDistance) {
  const std::vector<std::uint8_t> texture = leaf_texture();
  const double coverage = level0_coverage(texture);
  testing::write_rgba_png("leaves128.png", kLeafSide, kLeafSide, texture);
  for (const float distance : {1.0f, 10.0f, 40.0f}) {
    GltfSpec spec;
    spec.materials.push_back({.base_color = {0.6f, 0.6f, 0.6f, 1.0f}});
    spec.materials.push_back(leaf_material(8));
    // A grey backdrop behind the wall, and the wall (4 wide) facing +z.
    spec.quads.push_back(square({0, 0, -distance - 5.0f}, {1, 0, 0}, {0, 1, 0}, 60.0f, 0));
    spec.quads.push_back(square({0, 0, -distance}, {1, 0, 0}, {0, 1, 0}, 2.0f, 1));
    const float yfov = 0.5f;
    spec.cameras.push_back(
        {.position = {0, 0, 0}, .target = {0, 0, -1}, .yfov = yfov, .zfar = 200.0f});
    Renderer renderer(gltf_scene(testing::write_gltf("leaf-wall.gltf", spec)));
    const Image albedo = render_view(renderer, View::Albedo, ShadowSettings{});
    // The wall's half-width in pixels, less a pixel at its edges.
    const float half = 2.0f / (distance * std::tan(0.5f * yfov)) * 0.5f * kImage - 1.0f;
    long wall = 0, leaves = 0;
    for (int y = 0; y < kImage; ++y) {
      for (int x = 0; x < kImage; ++x) {
        const float px = static_cast<float>(x) + 0.5f - 0.5f * kImage;
        const float py = static_cast<float>(y) + 0.5f - 0.5f * kImage;
        if (std::abs(px) > half || std::abs(py) > half) continue;
        ++wall;
        leaves += is_leaf(albedo.pixel(x, y));
      }
    }
    const double seen = static_cast<double>(leaves) / static_cast<double>(wall);
    std::printf("distance %.0f: %ld of %ld wall pixels are leaves (%.3f; level 0: %.3f)\n",
                distance, leaves, wall, seen, coverage);
    ASSERT_GT(wall, 900);
    EXPECT_NEAR(seen / coverage, 1.0, 0.10) << distance;
  }
}

}  // namespace
}  // namespace penumbra
