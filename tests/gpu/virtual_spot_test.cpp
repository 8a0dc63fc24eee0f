// Virtual shadow maps for spot lights (--shadow-maps virtual,
// docs/rendering.md): the pages the GPU marks for a spot against a CPU
// computation of the pages each pixel reads; a page's texels against a
// conventional spot map of its level's projection and resolution; the
// shadow of every spot light against conventional maps of the levels'
// resolutions; the page cache; the pages and texel-density views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <tuple>

#include "gpu_fixture.hpp"
#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/traced_reference.hpp"
#include "render/gpu_scene.hpp"
#include "render/renderer.hpp"
#include "render/scene_shadow_casters.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::virtual_maps;

// The default scene, the camera nearer, lit by its spot alone; with `second_spot`, by a
// second spot too, from the other side of the objects.
Scene spot_scene(bool second_spot = false) {
  Scene scene = *builtin_scene("default");
  scene.lights.resize(1);  // less the sun
  EXPECT_EQ(scene.lights.front().type, LightType::Spot);
  // Close to the objects, over the ground behind them: the pixels'
  // footprints against the spot's texels there span several levels.
  scene.camera.position = {0.5f, 2.5f, 5.0f};
  scene.camera.target = {0.0f, 0.6f, -1.0f};
  if (second_spot) {
    Light spot = scene.lights.front();
    spot.position = {-4.0f, 8.0f, 3.0f};
    spot.direction = glm::normalize(glm::vec3(0.5f, 0.6f, 0.0f) - spot.position);
    scene.lights.push_back(spot);
  }
  return scene;
}

RenderSettings camera_view(View view, int light_index = 0) {
  RenderSettings rs = testing::small_frame(384, 256, view);
  rs.light_index = light_index;
  return rs;
}

// A spot light's virtual maps in the last render(), and the index of its
// first level among all virtual lights' (its first page-table layer).
struct SpotMaps {
  const VirtualLightMaps* maps = nullptr;
  int first_level = 0;
};

SpotMaps spot_maps(const Renderer& renderer, int light) {
  int first = 0;
  for (const VirtualLightMaps& m : renderer.virtual_lights()) {
    if (m.light_index == light) return {&m, first};
    first += static_cast<int>(m.maps.levels.size());
  }
  ADD_FAILURE() << "light " << light << " has no virtual maps";
  return {};
}

using Page = std::tuple<int, int, int>;  // the spot's level, page x, y

std::vector<GLuint> page_table(const Renderer& renderer) {
  std::vector<GLuint> entries(static_cast<std::size_t>(kVirtualPages) * kVirtualPages *
                              kMaxVirtualViews);
  glGetTextureImage(renderer.virtual_shadows().page_table().id(), 0, GL_RED_INTEGER,
                    GL_UNSIGNED_INT, static_cast<GLsizei>(entries.size() * sizeof(GLuint)),
                    entries.data());
  return entries;
}

GLuint entry_of(const std::vector<GLuint>& table, int layer, int x, int y) {
  return table[(static_cast<std::size_t>(layer) * kVirtualPages + static_cast<std::size_t>(y)) *
                   kVirtualPages +
               static_cast<std::size_t>(x)];
}

// The spot's resident pages. Entries outside a level's pages count too
// (as page (x, y) beyond it): none should be.
std::set<Page> resident_pages(const Renderer& renderer, int light) {
  const SpotMaps spot = spot_maps(renderer, light);
  const std::vector<GLuint> table = page_table(renderer);
  std::set<Page> pages;
  for (int m = 0; m < static_cast<int>(spot.maps->maps.levels.size()); ++m) {
    for (int y = 0; y < kVirtualPages; ++y) {
      for (int x = 0; x < kVirtualPages; ++x) {
        if ((entry_of(table, spot.first_level + m, x, y) & PAGE_RESIDENT) != 0u)
          pages.emplace(m, x, y);
      }
    }
  }
  return pages;
}

// Where a point falls in a spot level: its texel coordinates, or nothing
// outside the spot's frustum.
std::optional<glm::vec2> level_texel(const VirtualLevel& level, const glm::vec3& world) {
  const glm::vec4 clip = level.view.view_projection * glm::vec4(world, 1.0f);
  if (clip.w <= 0.0f) return std::nullopt;
  const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
  if (glm::any(glm::lessThan(uv, glm::vec2(0.0f))) ||
      glm::any(glm::greaterThan(uv, glm::vec2(1.0f))))
    return std::nullopt;
  return uv * static_cast<float>(level.texels);
}

// The pages of level m a lookup at texel `texel` reads, `reach` texels around it.
void add_pages(const VirtualClipmap& maps, int m, glm::vec2 texel, float reach,
               std::set<Page>& pages) {
  const int last_page = maps.levels[static_cast<std::size_t>(m)].texels / kVirtualPageTexels - 1;
  const glm::ivec2 first = glm::clamp(glm::ivec2(glm::floor((texel - reach) / 128.0f)),
                                      glm::ivec2(0), glm::ivec2(last_page));
  const glm::ivec2 last = glm::clamp(glm::ivec2(glm::floor((texel + reach) / 128.0f)),
                                     glm::ivec2(0), glm::ivec2(last_page));
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x) pages.emplace(m, x, y);
}

TEST_F(GpuTest, VirtualSpotPagesMarkedAreThoseThePixelsRead) {
  Renderer renderer(spot_scene());
  for (Technique t : {Technique::Hard, Technique::Pcf}) {
    renderer.render(camera_view(View::Shadow), virtual_maps(t));
    ASSERT_EQ(renderer.virtual_light(), -1) << "no directional light";
    ASSERT_EQ(renderer.virtual_lights().size(), 1u);
    const VirtualPageStats stats = renderer.virtual_page_stats();
    EXPECT_EQ(stats.unserved, 0);
    const std::set<Page> gpu = resident_pages(renderer, 0);
    EXPECT_EQ(static_cast<int>(gpu.size()), stats.resident);

    // The CPU's pages: those every pixel in the spot's frustum needs (its
    // reach less half a texel of rounding), and those it may mark (half a
    // texel more; both levels for a pixel within rounding of a level
    // boundary).
    const VirtualClipmap& maps = spot_maps(renderer, 0).maps->maps;
    const int levels = static_cast<int>(maps.levels.size());
    ASSERT_EQ(levels, kVirtualSpotLevels);
    const float reach = renderer.virtual_shadows().block().params.y;
    const SurfacePoints surfaces = renderer.read_surfaces();
    const std::vector<glm::vec3> facets = renderer.read_facet_normals();
    std::set<Page> needed, allowed;
    std::set<int> levels_seen;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      if (surfaces.covered[i] == 0) continue;
      const glm::vec3 p = surfaces.position[i];
      const int level = virtual_level_of(maps, p, facets[i], stats.bias);
      const auto texel = level_texel(maps.levels[static_cast<std::size_t>(level)], p);
      if (!texel) continue;
      // The level before flooring and clamping.
      const float f =
          virtual_level_coordinate(maps, p, facets[i]) - 0.5f * static_cast<float>(stats.bias);
      const bool boundary = std::abs(f - std::round(f)) < 1e-3f;
      const glm::vec2 edge = glm::min(*texel, float(maps.levels[level].texels) - *texel);
      if (!boundary && std::min(edge.x, edge.y) > 0.01f)
        add_pages(maps, level, *texel, reach - 0.5f, needed);
      add_pages(maps, level, *texel, reach + 0.5f, allowed);
      if (boundary) {
        for (int l : {level - 1, level + 1}) {
          if (l < 0 || l >= levels) continue;
          const auto other = level_texel(maps.levels[static_cast<std::size_t>(l)], p);
          if (other) add_pages(maps, l, *other, reach + 0.5f, allowed);
        }
      }
      levels_seen.insert(level);
    }
    EXPECT_GE(levels_seen.size(), 2u) << "the image spans several levels";
    ASSERT_FALSE(needed.empty());
    int missing = 0, extra = 0;
    for (const Page& p : needed) missing += gpu.count(p) == 0 ? 1 : 0;
    for (const Page& p : gpu) extra += allowed.count(p) == 0 ? 1 : 0;
    EXPECT_EQ(missing, 0) << "of " << needed.size() << " pages needed";
    EXPECT_EQ(extra, 0) << "of " << gpu.size() << " pages marked";
  }
}

// A page's texels equal those of a conventional spot map with its level's
// projection and depth range at its level's resolution (ShadowMapPass:
// reversed depth, linearized to z-bar), over the page's square.
TEST_F(GpuTest, VirtualSpotPageTexelsEqualAConventionalMap) {
  const Scene scene = spot_scene();
  Renderer renderer(scene);
  const ShadowSettings shadow = virtual_maps(Technique::Hard);
  renderer.render(camera_view(View::Shadow), shadow);
  const std::set<Page> pages = resident_pages(renderer, 0);
  ASSERT_FALSE(pages.empty());
  const SpotMaps spot = spot_maps(renderer, 0);
  const std::vector<GLuint> table = page_table(renderer);
  const gl::Texture& pool = renderer.virtual_shadows().pool();

  const TriangleMesh mesh = build_scene_mesh(scene);
  GpuScene gpu_scene(scene, mesh);
  SceneShadowCasters casters;
  ShadowMapPass conventional;
  gl::Buffer views_ubo(sizeof(gpu::GpuShadowView) * MAX_SHADOW_VIEWS, nullptr, true, "views");
  std::map<int, std::vector<float>> maps;  // per level, its whole conventional map
  int compared = 0;
  for (const auto& [level, px, py] : pages) {
    const VirtualLevel& lv = spot.maps->maps.levels[static_cast<std::size_t>(level)];
    ASSERT_TRUE(lv.view.perspective);
    if (lv.texels > 2048) continue;  // keeps the conventional maps small
    const int n = lv.texels;
    if (maps.count(level) == 0) {
      gpu::GpuShadowView v = gpu_shadow_view(spot.maps->light, lv.view, shadow);
      v.depth_range.w = static_cast<float>(n);
      views_ubo.update(&v, sizeof v);
      glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_SHADOW_VIEWS_UBO, views_ubo.id());
      conventional.execute([&](int view) { casters.draw(gpu_scene, view, false); },
                           std::span<const gpu::GpuShadowView>(&v, 1), n, {});
      std::vector<float>& map = maps[level];
      map.resize(static_cast<std::size_t>(n) * n);
      glGetTextureImage(conventional.depth_maps().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                        static_cast<GLsizei>(map.size() * sizeof(float)), map.data());
    }
    const std::vector<float>& map = maps[level];
    const GLuint entry = entry_of(table, spot.first_level + level, px, py);
    ASSERT_NE(entry & PAGE_RESIDENT, 0u);
    const int t = kVirtualPageTexels;
    std::vector<float> actual(static_cast<std::size_t>(t) * t);
    glGetTextureSubImage(pool.id(), 0, 0, 0, static_cast<GLint>(entry & PAGE_INDEX_MASK), t, t, 1,
                         GL_DEPTH_COMPONENT, GL_FLOAT,
                         static_cast<GLsizei>(actual.size() * sizeof(float)), actual.data());
    int covered = 0, differing = 0;
    float largest = 0.0f;
    for (int y = 0; y < t; ++y) {
      for (int x = 0; x < t; ++x) {
        const float e = map[static_cast<std::size_t>(py * t + y) * n + px * t + x];
        const float a = actual[static_cast<std::size_t>(y) * t + x];
        covered += e < 1.0f ? 1 : 0;
        const float d = std::abs(e - a);
        // A texel whose centre lies on a triangle's edge may fall either
        // side of it in the two projections (they round differently).
        if (d > 1e-5f)
          ++differing;
        else
          largest = std::max(largest, d);
      }
    }
    if (covered == 0) continue;
    ++compared;
    EXPECT_LE(differing, t * t / 200) << "page " << level << " (" << px << ", " << py << ")";
    EXPECT_LT(largest, 1e-5f);
  }
  EXPECT_GE(compared, 3) << "pages with casters compared";
}

// Each pixel's level (virtual_level_of()) of light `light`'s virtual maps,
// -1 outside its frustum or where the level's conventional map would be
// over 2048^2.
std::vector<int> pixel_levels(const Renderer& renderer, int light, const SurfacePoints& surfaces) {
  const VirtualClipmap& maps = spot_maps(renderer, light).maps->maps;
  const std::vector<glm::vec3> facets = renderer.read_facet_normals();
  const int bias = renderer.virtual_page_stats().bias;
  std::vector<int> levels(surfaces.size(), -1);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (surfaces.covered[i] == 0) continue;
    const int level = virtual_level_of(maps, surfaces.position[i], facets[i], bias);
    const VirtualLevel& lv = maps.levels[static_cast<std::size_t>(level)];
    if (lv.texels <= 2048 && level_texel(lv, surfaces.position[i])) levels[i] = level;
  }
  return levels;
}

// Every spot light's hard shadow through its virtual maps is the one its
// conventional map gives at the resolution of the level each pixel reads,
// on at least 99 % of the pixels in its frustum; its texel density (the
// resident level's texel, virtual_shading_texel()) is that map's too.
TEST_F(GpuTest, VirtualSpotShadowsAgreeWithConventionalMapsOfTheLevelsResolution) {
  Renderer renderer(spot_scene(true));
  for (int light = 0; light < 2; ++light) {
    ShadowSettings shadow = virtual_maps(Technique::Hard);
    // A pool with no room for finer levels (the level bias stays 0), so
    // that the levels read have conventional maps of at most 2048^2.
    shadow.page_pool_mib = 12;
    renderer.render(camera_view(View::Shadow, light), shadow);
    ASSERT_EQ(renderer.virtual_lights().size(), 2u) << "every spot light";
    ASSERT_EQ(renderer.virtual_page_stats().bias, 0);
    ASSERT_EQ(renderer.virtual_page_stats().unserved, 0);
    const Image actual = renderer.read_view();
    const Image actual_density = renderer.read_texel_density();
    const SurfacePoints surfaces = renderer.read_surfaces();
    const std::vector<int> levels = pixel_levels(renderer, light, surfaces);
    std::set<int> used(levels.begin(), levels.end());
    used.erase(-1);
    const VirtualClipmap maps = spot_maps(renderer, light).maps->maps;

    std::vector<float> expected(surfaces.size(), -1.0f), expected_density(surfaces.size(), -1.0f);
    for (int level : used) {
      if (level < 0) continue;
      ShadowSettings conventional;
      conventional.technique = Technique::Hard;
      conventional.map_size = maps.levels[static_cast<std::size_t>(level)].texels;
      renderer.render(camera_view(View::Shadow, light), conventional);
      const Image image = renderer.read_view();
      const Image density = renderer.read_texel_density();
      for (std::size_t i = 0; i < levels.size(); ++i) {
        if (levels[i] != level) continue;
        expected[i] = image.rgba[4 * i];
        expected_density[i] = density.rgba[4 * i];
      }
    }
    int compared = 0, differing = 0, shadowed = 0, density_compared = 0, density_differing = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      if (expected[i] < 0.0f || actual.rgba[4 * i + 3] < 0.5f) continue;
      ++compared;
      shadowed += expected[i] < 0.5f ? 1 : 0;
      differing += std::abs(expected[i] - actual.rgba[4 * i]) > 0.5f ? 1 : 0;
      if (expected_density[i] > 0.0f) {
        ++density_compared;
        const float ratio = actual_density.rgba[4 * i] / expected_density[i];
        density_differing += std::abs(ratio - 1.0f) > 1e-3f ? 1 : 0;
      }
    }
    EXPECT_GE(used.size(), 2u) << "light " << light << ": the image spans several levels";
    EXPECT_GT(compared, static_cast<int>(surfaces.size()) / 4) << "light " << light;
    EXPECT_GT(shadowed, compared / 50) << "light " << light << ": the view shows shadows";
    EXPECT_LE(differing, compared / 100) << "light " << light;
    EXPECT_GT(density_compared, compared / 2) << "light " << light;
    EXPECT_LE(density_differing, density_compared / 100) << "light " << light;
  }
}

// The page cache for a spot: a static frame renders no page; a moved
// shape renders only the spot's pages its old and new bounds touch; the
// image equals the one rendered with every page drawn anew.
TEST_F(GpuTest, VirtualSpotPagesAreCachedUntilACasterOverThemMoves) {
  Renderer renderer(spot_scene());
  const RenderSettings render = camera_view(View::Shadow);
  const ShadowSettings shadow = virtual_maps(Technique::Pcf);
  renderer.render(render, shadow);
  const VirtualPageStats first = renderer.virtual_page_stats();
  EXPECT_GT(first.rendered, 0);
  EXPECT_EQ(first.rendered, first.resident);
  renderer.render(render, shadow);
  EXPECT_EQ(renderer.virtual_page_stats().rendered, 0) << "a static frame";
  EXPECT_EQ(renderer.virtual_page_stats().resident, first.resident);
  const std::set<Page> resident_before = resident_pages(renderer, 0);

  // The sphere (shape 2) moves a little: of the pages cached before, the
  // spot's pages its boxes touch, at each level, are all that render again
  // (besides the pages the pixels it uncovered or covered ask for anew).
  const std::size_t sphere = 2;
  const Bounds before = renderer.shape_bounds(sphere);
  renderer.move_shape(sphere, {0.3f, 0.0f, 0.0f});
  const Bounds after = renderer.shape_bounds(sphere);
  renderer.render(render, shadow);
  const VirtualPageStats moved = renderer.virtual_page_stats();
  const Image cached = renderer.read_view();
  const std::set<Page> resident = resident_pages(renderer, 0);
  const VirtualClipmap& maps = spot_maps(renderer, 0).maps->maps;
  int touched = 0;
  for (std::size_t m = 0; m < maps.levels.size(); ++m) {
    std::set<Page> pages;
    for (const Bounds& b : {before, after}) {
      const auto [lo, hi] = virtual_pages_of_box(maps.levels[m], b.min, b.max);
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) pages.emplace(static_cast<int>(m), x, y);
    }
    for (const Page& p : pages) {
      touched += static_cast<int>(resident.count(p) * resident_before.count(p));
    }
  }
  int allocated = 0;  // pages this frame asked for that were not resident before
  for (const Page& p : resident) allocated += resident_before.count(p) == 0 ? 1 : 0;
  EXPECT_EQ(moved.bias, first.bias);
  EXPECT_GT(moved.rendered, 0);
  EXPECT_LE(allocated, moved.rendered);
  EXPECT_LE(moved.rendered - allocated, touched) << "only the cached pages the sphere touches";
  EXPECT_LT(touched, moved.resident) << "the sphere's boxes miss some resident pages";
  renderer.forget_shadow_maps();
  renderer.render(render, shadow);
  EXPECT_EQ(renderer.virtual_page_stats().rendered, renderer.virtual_page_stats().resident);
  EXPECT_EQ(cached.rgba, renderer.read_view().rgba);
}

// Backprojection through a spot light's virtual maps, source 1.0 wide,
// against the traced reference. Its cut of the cone to the source reads
// the depth bounds of the pages' cells, which the bounds pass made only for
// the orthographic levels' pages: a spot's pages read bounds of 0, and
// receivers took the umbra's early exit (before: RMSE 0.80, 56 % of the
// pixels over-dark; now 0.0166, 0.003 %).
TEST_F(GpuTest, VirtualSpotBackprojectionReadsItsPagesDepthBounds) {
  Renderer renderer(spot_scene());
  const RenderSettings rs = camera_view(View::Shadow);
  ShadowSettings shadow = virtual_maps(Technique::Backprojection);
  shadow.light_size = 1.0f;
  const TracedReference reference = traced_reference(renderer, rs, shadow, 64, "");
  renderer.render(rs, shadow);
  const ShadowMetrics m = compare_shadow(renderer.read_view(), reference.image);
  std::printf("virtual spot backprojection: RMSE %.4f, over-dark %.3f %%\n", m.rmse,
              100.0 * m.over_dark_fraction);
  EXPECT_LT(m.rmse, 0.03);
  EXPECT_LT(m.over_dark_fraction, 0.001);
}

// --view pages for a spot: inside its frustum every pixel shows the page
// it reads, a colour per level; outside it, black.
TEST_F(GpuTest, VirtualSpotPagesView) {
  Renderer renderer(spot_scene());
  renderer.render(camera_view(View::Pages), virtual_maps(Technique::Hard));
  const Image image = renderer.read_view();
  const SurfacePoints surfaces = renderer.read_surfaces();
  const VirtualClipmap& maps = spot_maps(renderer, 0).maps->maps;
  const std::vector<glm::vec3> facets = renderer.read_facet_normals();
  const int bias = renderer.virtual_page_stats().bias;
  std::map<int, glm::vec3> colour_sum;
  std::map<int, int> count;
  int inside = 0, shown = 0, outside = 0, outside_black = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    if (surfaces.covered[i] == 0) continue;
    const glm::vec3 c(image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]);
    const bool black = std::max({c.x, c.y, c.z}) < 1e-3f;
    const int level = virtual_level_of(maps, surfaces.position[i], facets[i], bias);
    const auto texel =
        level_texel(maps.levels[static_cast<std::size_t>(level)], surfaces.position[i]);
    if (!texel) {
      ++outside;
      outside_black += black ? 1 : 0;
      continue;
    }
    ++inside;
    shown += black ? 0 : 1;
    colour_sum[level] += c;
    ++count[level];
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GE(shown, inside * 99 / 100);
  EXPECT_EQ(outside_black, outside);
  ASSERT_GE(count.size(), 2u) << "several levels in view";
  const auto a = count.begin(), b = std::next(a);
  EXPECT_GT(glm::length(colour_sum[a->first] / float(a->second) -
                        colour_sum[b->first] / float(b->second)),
            0.1f)
      << "levels " << a->first << " and " << b->first << " in different colours";
}

}  // namespace
}  // namespace penumbra
