// Shadow lookups from the smooth surface: a coarse smooth-shaded sphere
// (an icosahedron split once, 80 flat triangles, vertex normals pointing
// away from its centre) lit from the side. Each pixel's lookup starts
// where the traced reference starts its rays (the terminator model,
// src/reference/terminator_offset.hpp): raised towards the smooth surface
// the vertex normals describe where the light grazes it, on its triangle
// elsewhere, and compared against the triangle's own plane
// (shaders/scene/smooth_surface.glsl), which the map holds, with the
// default biases. The lit side stays lit where the reference lights it,
// and the shadow view judges the same pixels as the reference: every one
// with some of the source above its shading normal's horizon, also where
// the light is below the triangle's own plane (as Cycles does).
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <utility>

#include "gpu_fixture.hpp"
#include "penumbra/shared/gpu_types.h"
#include "reference/traced_reference.hpp"
#include "render/gbuffer_pass.hpp"
#include "render/gpu_scene.hpp"
#include "render/renderer.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

const glm::vec3 kCentre{0.0f, 1.2f, 0.0f};

// The icosahedron split once, on the unit sphere: every vertex's normal is
// its position, the smooth sphere's.
std::shared_ptr<Model> coarse_sphere() {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<glm::vec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                   {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                   {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (glm::vec3& p : points) p = glm::normalize(p);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middles;
  auto middle = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    auto it = middles.find(key);
    if (it != middles.end()) return it->second;
    points.push_back(glm::normalize(points[a] + points[b]));
    return middles[key] = static_cast<std::uint32_t>(points.size() - 1);
  };
  auto model = std::make_shared<Model>();
  model->materials.push_back(Material{"clay", glm::vec3(0.7f), glm::vec3(0.0f), 8.0f});
  for (const auto& f : faces) {
    const std::uint32_t ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
    for (const std::array<std::uint32_t, 3>& split :
         {std::array{f[0], ab, ca}, std::array{f[1], bc, ab}, std::array{f[2], ca, bc},
          std::array{ab, bc, ca}}) {
      model->mesh.indices.insert(model->mesh.indices.end(), split.begin(), split.end());
    }
  }
  for (const glm::vec3& p : points) model->mesh.vertices.push_back(Vertex{p, p, 0});
  model->bounds = model->mesh.bounds();
  return model;
}

// The sphere over a plane, seen from the front, a spot light to its right
// and a little above, so that the terminator runs down the sphere's middle.
Scene sphere_scene() {
  Shape sphere;
  sphere.kind = ShapeKind::Model;
  sphere.model = coarse_sphere();
  sphere.position = kCentre;
  return testing::TestScene("coarse sphere")
      .ground(12.0f)
      .shape(sphere)
      .camera({0.0f, 1.5f, 4.5f}, kCentre, 30.0f)
      .light(testing::spot_light({6.0f, 2.5f, 0.0f}, kCentre, 25.0f, 20.0f));
}

// The scene's shadow view at 160 x 120 with `shadow`, and the traced
// reference with `rays` rays a pixel.
struct SphereImages {
  Image shadow, reference;
  SurfacePoints surfaces;
  // Whether pixel i shows the sphere (the ground's pixels outside the
  // spot's cone are not judged by the reference alone).
  bool on_sphere(std::size_t i) const {
    return surfaces.covered[i] && glm::length(surfaces.position[i] - kCentre) <= 1.01f;
  }
};
SphereImages sphere_images(const Scene& scene, const ShadowSettings& shadow, int rays) {
  Renderer renderer(scene);
  const RenderSettings rs = testing::small_frame(160, 120);
  TracedReference reference = traced_reference(renderer, rs, shadow, rays, "");
  SphereImages images{Image{}, std::move(reference.image), renderer.read_surfaces()};
  renderer.render(rs, shadow);
  images.shadow = renderer.read_view();
  return images;
}

TEST_F(GpuTest, ShadowLookupsStartOnTheSmoothSurfaceOfACoarseMesh) {
  ShadowSettings shadow;  // hard shadows from a point, the default biases
  shadow.map_size = 1024;
  shadow.light_size = 0.0f;
  const SphereImages images = sphere_images(sphere_scene(), shadow, 1);
  const Image& image = images.shadow;
  const Image& reference_image = images.reference;
  int lit = 0, shadowed = 0, judged_differently = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
      if (!images.on_sphere(i)) continue;
      if ((reference_image.pixel(x, y)[3] > 0.0f) != (image.pixel(x, y)[3] > 0.0f)) {
        ++judged_differently;
      }
      if (reference_image.pixel(x, y)[3] == 0.0f) continue;
      if (reference_image.pixel(x, y)[0] < 1.0f) continue;
      ++lit;
      if (image.pixel(x, y)[0] < 0.5f) ++shadowed;
    }
  }
  std::printf("sphere pixels the reference lights: %d, %d shadowed; %d judged differently\n", lit,
              shadowed, judged_differently);
  ASSERT_GT(lit, 2000);
  EXPECT_LE(shadowed, lit / 200);
  EXPECT_LE(judged_differently, 10);
}

// The sphere with a wall between it and the light hiding its lower half,
// under a source 1.5 wide. Near the terminator a triangle's plane and its
// shading normal's horizon are up to the angle between its normals apart
// (up to 21 degrees on this sphere), and the rays that count run between
// them to the part of the source below the triangle's plane: blockers
// there (the wall) count. Backprojection kept only the blockers within
// 0.1 of a sine below the plane, and the wall's umbra on the sphere leaked
// (before: RMSE 0.0880 over the sphere's judged pixels, 27 of 341 umbra
// pixels over 0.1; with twice the sine of that angle: 0.0248, none).
TEST_F(GpuTest, BackprojectionKeepsTheBlockersBelowATrianglesPlaneAboveItsShadingHorizon) {
  Scene scene = sphere_scene();
  Shape wall;
  wall.kind = ShapeKind::Box;
  wall.size = {0.05f, 1.8f, 4.0f};
  wall.position = {3.0f, 0.9f, 0.0f};
  scene.shapes.push_back(wall);
  ShadowSettings shadow;
  shadow.technique = Technique::Backprojection;
  shadow.map_size = 1024;
  shadow.light_size = 1.5f;
  const SphereImages images = sphere_images(scene, shadow, 256);
  double sum = 0.0;
  int pixels = 0, umbra = 0, leaks = 0;
  for (std::size_t i = 0; i < images.shadow.rgba.size() / 4; ++i) {
    const float reference = images.reference.rgba[4 * i], lit = images.shadow.rgba[4 * i];
    if (!images.on_sphere(i) || images.reference.rgba[4 * i + 3] == 0.0f) continue;
    sum += (lit - reference) * (lit - reference);
    ++pixels;
    if (reference > 0.01f) continue;
    ++umbra;
    if (lit > 0.1f) ++leaks;
  }
  const double rmse = std::sqrt(sum / pixels);
  std::printf("sphere: %d pixels, RMSE %.4f; %d of %d umbra pixels over 0.1\n", pixels, rmse, leaks,
              umbra);
  ASSERT_GT(umbra, 200) << "too little of the wall's umbra on the sphere";
  EXPECT_LT(rmse, 0.04);
  EXPECT_LE(leaks, umbra / 50);
}

// The G-buffer's triangle normals and rises, drawn with the scene's
// corners readable and with a storage-block limit they exceed (a scene of
// more than 128 MiB of vertices on Mesa): then the point stays on its
// triangle, and the triangle's normal comes from the position's
// screen-space derivatives, the same plane.
TEST_F(GpuTest, TheGBufferKeepsTheTrianglesNormalsWhenItCannotReadTheCorners) {
  const Scene scene = sphere_scene();
  const TriangleMesh mesh = build_scene_mesh(scene);
  const Renderer renderer(scene);
  const int width = 96, height = 72;
  gpu::GpuFrame frame{};
  frame.view = renderer.camera_view();
  frame.projection = renderer.camera_projection(width, height);
  frame.inverse_view_projection = glm::inverse(frame.projection * frame.view);
  gl::Buffer frame_block(sizeof frame, &frame, false, "frame block");
  glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_FRAME_UBO, frame_block.id());
  std::vector<float> facets[2];
  for (const bool readable : {true, false}) {
    const GpuScene gpu_scene(scene, mesh, readable ? -1 : 1024);
    ASSERT_EQ(gpu_scene.corners_readable(), readable);
    GBufferPass pass;
    pass.execute(gpu_scene, width, height);
    std::vector<float>& facet = facets[readable ? 0 : 1];
    facet.resize(static_cast<std::size_t>(width) * height * 4);
    glGetTextureImage(pass.facet().id(), 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(facet.size() * sizeof(float)), facet.data());
  }
  int sphere = 0, raised = 0, same_plane = 0;
  float highest = 0.0f;
  for (std::size_t i = 0; i < facets[0].size(); i += 4) {
    const glm::vec3 corners(facets[0][i], facets[0][i + 1], facets[0][i + 2]);
    const glm::vec3 derivatives(facets[1][i], facets[1][i + 1], facets[1][i + 2]);
    if (glm::length(corners) < 0.5f || corners.y > 0.999f) continue;  // background, ground
    ++sphere;
    EXPECT_EQ(facets[1][i + 3], 0.0f);  // without the corners, no rise
    if (facets[0][i + 3] > 1e-4f) ++raised;
    highest = std::max(highest, facets[0][i + 3]);
    // Half floats: the normals agree to their 11 bits.
    if (glm::dot(glm::normalize(corners), glm::normalize(derivatives)) > 0.9999f) ++same_plane;
  }
  std::printf("sphere pixels %d: %d raised (at most %.4f), %d on the same plane both ways\n",
              sphere, raised, highest, same_plane);
  ASSERT_GT(sphere, 1000);
  EXPECT_GT(raised, sphere / 2);
  // The terminator model's rise on this mesh (edges spanning 31.7 degrees
  // of the unit sphere; smooth_surface_rise) peaks at 0.1189, computed on
  // the CPU over a fine barycentric grid of every face: the pixels come
  // near it, and never beyond.
  EXPECT_GT(highest, 0.10f);
  EXPECT_LT(highest, 0.12f);
  EXPECT_GE(same_plane, sphere - sphere / 100);
}

}  // namespace
}  // namespace penumbra
