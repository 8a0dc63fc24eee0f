// Virtual shadow maps (--shadow-maps virtual, docs/rendering.md): the
// pages the GPU marks against a CPU computation of the pages each pixel
// reads; a page's texels against a conventional orthographic map of the
// same projection; the page cache. (The shadow across page and level
// borders: virtual_seam_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <set>
#include <tuple>

#include "gpu_fixture.hpp"
#include "penumbra/shadow/shadow_block_data.hpp"
#include "penumbra/shadow/shadow_map_pass.hpp"
#include "render/gpu_scene.hpp"
#include "render/renderer.hpp"
#include "render/scene_shadow_casters.hpp"
#include "render/virtual_page_orbit.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::virtual_maps;

// The default scene under its sun alone.
Scene sun_scene() {
  Scene scene = *builtin_scene("default");
  scene.lights.erase(scene.lights.begin());
  EXPECT_EQ(scene.lights.front().type, LightType::Directional);
  return scene;
}

RenderSettings shadow_view(int width, int height) {
  RenderSettings rs;
  rs.width = width;
  rs.height = height;
  rs.view = View::Shadow;
  return rs;
}

using Page = std::tuple<int, int, int>;  // level, world page x, y

// The resident pages of the page table, as (level, world page).
std::set<Page> resident_pages(const Renderer& renderer) {
  const gl::Texture& table = renderer.virtual_shadows().page_table();
  std::vector<GLuint> entries(static_cast<std::size_t>(kVirtualPages) * kVirtualPages *
                              kMaxVirtualViews);
  glGetTextureImage(table.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    static_cast<GLsizei>(entries.size() * sizeof(GLuint)), entries.data());
  const VirtualClipmap& clipmap = renderer.virtual_clipmap();
  std::set<Page> pages;
  for (std::size_t l = 0; l < clipmap.levels.size(); ++l) {
    const glm::ivec2 origin = clipmap.levels[l].origin;
    for (int y = 0; y < kVirtualPages; ++y) {
      for (int x = 0; x < kVirtualPages; ++x) {
        const GLuint e = entries[(l * kVirtualPages + static_cast<std::size_t>(y)) * kVirtualPages +
                                 static_cast<std::size_t>(x)];
        if ((e & PAGE_RESIDENT) == 0u) continue;
        const glm::ivec2 world = origin + ((glm::ivec2(x, y) - origin) & (kVirtualPages - 1));
        pages.emplace(static_cast<int>(l), world.x, world.y);
      }
    }
  }
  return pages;
}

// The pages of `level` a lookup at `world` reads, `reach` texels around it.
void add_pages(const VirtualClipmap& clipmap, int level, const glm::vec3& world, float reach,
               std::set<Page>& pages) {
  const VirtualLevel& lv = clipmap.levels[static_cast<std::size_t>(level)];
  const glm::vec4 clip = lv.view.view_projection * glm::vec4(world, 1.0f);
  const glm::vec2 texel = (glm::vec2(clip) * 0.5f + 0.5f) * float(kVirtualTexels);
  const glm::ivec2 first = glm::clamp(glm::ivec2(glm::floor((texel - reach) / 128.0f)),
                                      glm::ivec2(0), glm::ivec2(kVirtualPages - 1));
  const glm::ivec2 last = glm::clamp(glm::ivec2(glm::floor((texel + reach) / 128.0f)),
                                     glm::ivec2(0), glm::ivec2(kVirtualPages - 1));
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) pages.emplace(level, lv.origin.x + x, lv.origin.y + y);
  }
}

TEST_F(GpuTest, VirtualPagesMarkedAreThoseThePixelsRead) {
  Renderer renderer(sun_scene());
  const RenderSettings render = shadow_view(96, 64);
  for (Technique t : {Technique::Hard, Technique::Pcf}) {
    const ShadowSettings shadow = virtual_maps(t);
    renderer.render(render, shadow);
    ASSERT_EQ(renderer.virtual_light(), 0);
    const VirtualPageStats stats = renderer.virtual_page_stats();
    EXPECT_EQ(stats.unserved, 0);
    const std::set<Page> gpu = resident_pages(renderer);
    EXPECT_EQ(static_cast<int>(gpu.size()), stats.resident);

    // The CPU's pages: those every pixel needs (its reach less half a
    // texel of rounding), and those it may mark (half a texel more; both
    // levels for a pixel within rounding of a level boundary).
    const VirtualClipmap& clipmap = renderer.virtual_clipmap();
    const float reach = renderer.virtual_shadows().block().params.y;
    const SurfacePoints surfaces = renderer.read_surfaces();
    const std::vector<glm::vec3> facets = renderer.read_facet_normals();
    std::set<Page> needed, allowed, levels_seen;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      if (surfaces.covered[i] == 0) continue;
      const glm::vec3 p = surfaces.position[i];
      const int level = virtual_level_of(clipmap, p, facets[i], stats.bias);
      const float f =
          virtual_level_coordinate(clipmap, p, facets[i]) - 0.5f * static_cast<float>(stats.bias);
      const bool boundary = std::abs(f - std::round(f)) < 1e-3f;
      if (!boundary) add_pages(clipmap, level, p, reach - 0.5f, needed);
      add_pages(clipmap, level, p, reach + 0.5f, allowed);
      if (boundary) {
        for (int l : {level - 1, level + 1}) {
          if (l >= 0 && l < static_cast<int>(clipmap.levels.size())) {
            add_pages(clipmap, l, p, reach + 0.5f, allowed);
          }
        }
      }
      levels_seen.emplace(level, 0, 0);
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

// A page's texels equal those of a conventional orthographic map over the
// page's square with its level's depth range, drawn by ShadowMapPass.
TEST_F(GpuTest, VirtualPageTexelsEqualAConventionalMap) {
  const Scene scene = sun_scene();
  Renderer renderer(scene);
  const ShadowSettings shadow = virtual_maps(Technique::Hard);
  renderer.render(shadow_view(96, 64), shadow);
  const std::set<Page> pages = resident_pages(renderer);
  ASSERT_FALSE(pages.empty());

  const gl::Texture& table = renderer.virtual_shadows().page_table();
  const gl::Texture& pool = renderer.virtual_shadows().pool();
  const VirtualClipmap& clipmap = renderer.virtual_clipmap();
  const TriangleMesh mesh = build_scene_mesh(scene);
  GpuScene gpu_scene(scene, mesh);
  SceneShadowCasters casters;
  ShadowMapPass conventional;
  gl::Buffer views_ubo(sizeof(gpu::GpuShadowView) * MAX_SHADOW_VIEWS, nullptr, true, "views");
  int compared = 0;
  for (const auto& [level, px, py] : pages) {
    const VirtualLevel& lv = clipmap.levels[static_cast<std::size_t>(level)];
    const float size = lv.view.texel_world * kVirtualPageTexels;
    LightView page_view = lv.view;
    page_view.projection =
        glm::ortho(px * size, (px + 1) * size, py * size, (py + 1) * size, lv.view.z0, lv.view.z1);
    page_view.view_projection = page_view.projection * page_view.view;
    gpu::GpuShadowView v = gpu_shadow_view(scene.lights.front(), page_view, shadow);
    v.depth_range.w = kVirtualPageTexels;
    views_ubo.update(&v, sizeof v);
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_SHADOW_VIEWS_UBO, views_ubo.id());
    conventional.execute([&](int view) { casters.draw(gpu_scene, view, false); },
                         std::span<const gpu::GpuShadowView>(&v, 1), kVirtualPageTexels, {});
    const int n = kVirtualPageTexels * kVirtualPageTexels;
    std::vector<float> expected(n), actual(n);
    glGetTextureSubImage(conventional.depth_maps().id(), 0, 0, 0, 0, kVirtualPageTexels,
                         kVirtualPageTexels, 1, GL_DEPTH_COMPONENT, GL_FLOAT, n * 4,
                         expected.data());
    const glm::ivec2 slot = virtual_page_slot({px, py});
    GLuint entry = 0;
    glGetTextureSubImage(table.id(), 0, slot.x, slot.y, level, 1, 1, 1, GL_RED_INTEGER,
                         GL_UNSIGNED_INT, sizeof entry, &entry);
    ASSERT_NE(entry & PAGE_RESIDENT, 0u);
    glGetTextureSubImage(pool.id(), 0, 0, 0, static_cast<GLint>(entry & PAGE_INDEX_MASK),
                         kVirtualPageTexels, kVirtualPageTexels, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         n * 4, actual.data());
    int covered = 0, differing = 0;
    float largest = 0.0f;
    for (int i = 0; i < n; ++i) {
      covered += expected[i] < 1.0f ? 1 : 0;
      const float d = std::abs(expected[i] - actual[i]);
      // A texel whose centre lies on a triangle's edge may fall either side
      // of it in the two projections (they round differently).
      if (d > 1e-5f)
        ++differing;
      else
        largest = std::max(largest, d);
    }
    if (covered == 0) continue;
    ++compared;
    EXPECT_LE(differing, n / 200) << "page " << level << " (" << px << ", " << py << ")";
    EXPECT_LT(largest, 1e-5f);
  }
  EXPECT_GE(compared, 3) << "pages with casters compared";
}

// Virtual maps shade as the cascades do where both have texels enough:
// the default scene's shadow factor under the sun, hard and pcf, against
// the cascades' at 4096^2 (whose texels there are as small as the
// levels'), differing only along the shadows' edges. (Virtual pcf's
// window is pcf_width pixel footprints, 1 to 2 texels each, so that it
// does not double at a level border: its penumbrae are up to twice the
// cascades', and more of their pixels differ.)
TEST_F(GpuTest, VirtualShadowsAgreeWithFineCascades) {
  Renderer renderer(sun_scene());
  const RenderSettings render = shadow_view(96, 64);
  for (Technique t : {Technique::Hard, Technique::Pcf}) {
    ShadowSettings cascades;
    cascades.technique = t;
    cascades.map_size = 4096;
    renderer.render(render, cascades);
    const Image expected = renderer.read_view();
    renderer.render(render, virtual_maps(t));
    const Image actual = renderer.read_view();
    int compared = 0, differing = 0, shadowed = 0;
    for (std::size_t p = 0; p < expected.rgba.size(); p += 4) {
      if (expected.rgba[p + 3] < 0.5f) continue;
      ++compared;
      shadowed += expected.rgba[p] < 0.5f ? 1 : 0;
      differing += std::abs(expected.rgba[p] - actual.rgba[p]) > 0.5f ? 1 : 0;
    }
    EXPECT_GT(shadowed, compared / 50) << "the view shows shadows";
    EXPECT_LE(differing, compared / (t == Technique::Pcf ? 40 : 100))
        << enum_name<Technique>(kTechniqueNames, t);
  }
}

// The page cache: a static frame renders no page; a moved shape renders
// only the pages its old and new bounds touch; each image equals the one
// rendered with every page drawn anew.
TEST_F(GpuTest, VirtualPagesAreCachedUntilACasterOverThemMoves) {
  Renderer renderer(sun_scene());
  const RenderSettings render = shadow_view(96, 64);
  const ShadowSettings shadow = virtual_maps(Technique::Pcf);
  renderer.render(render, shadow);
  const VirtualPageStats first = renderer.virtual_page_stats();
  EXPECT_GT(first.rendered, 0);
  EXPECT_EQ(first.rendered, first.resident);
  renderer.render(render, shadow);
  EXPECT_EQ(renderer.virtual_page_stats().rendered, 0) << "a static frame";
  EXPECT_EQ(renderer.virtual_page_stats().resident, first.resident);
  const std::set<Page> resident_before = resident_pages(renderer);

  // The sphere (shape 2) moves a little: of the pages cached before, those
  // its boxes touch, at each level, are all that render again (besides the
  // pages the pixels it uncovered or covered ask for anew).
  const std::size_t sphere = 2;
  const Bounds before = renderer.shape_bounds(sphere);
  renderer.move_shape(sphere, {0.3f, 0.0f, 0.0f});
  const Bounds after = renderer.shape_bounds(sphere);
  renderer.render(render, shadow);
  const VirtualPageStats moved = renderer.virtual_page_stats();
  const Image cached = renderer.read_view();
  const std::set<Page> resident = resident_pages(renderer);
  int touched = 0;
  const VirtualClipmap& clipmap = renderer.virtual_clipmap();
  for (std::size_t l = 0; l < clipmap.levels.size(); ++l) {
    std::set<Page> pages;
    for (const Bounds& b : {before, after}) {
      const auto [lo, hi] = virtual_pages_of_box(clipmap.levels[l], b.min, b.max);
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) pages.emplace(static_cast<int>(l), x, y);
    }
    for (const Page& p : pages) touched += resident.count(p) * resident_before.count(p);
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

// An orbiting camera over a static scene: after the first frame, the
// pages rendered are those that came into view, at most a tenth of those
// allocated (penumbra bench prints the same rows).
TEST_F(GpuTest, OrbitingCameraRendersFewVirtualPages) {
  Renderer renderer(sun_scene());
  const std::vector<VirtualOrbitFrame> orbit =
      orbit_virtual_pages(renderer, shadow_view(320, 200), virtual_maps(Technique::Hard), 12, 1.0f);
  ASSERT_EQ(orbit.size(), 12u);
  EXPECT_EQ(orbit.front().rendered, orbit.front().resident);
  int rendered = 0, allocated = 0;
  for (std::size_t f = 1; f < orbit.size(); ++f) {
    rendered += orbit[f].rendered;
    allocated += orbit[f].resident;
  }
  EXPECT_GT(allocated, 0);
  EXPECT_LE(rendered * 10, allocated) << rendered << " pages rendered of " << allocated;
}

}  // namespace
}  // namespace penumbra
