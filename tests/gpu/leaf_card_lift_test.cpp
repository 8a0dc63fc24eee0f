// Thin double-sided cards whose vertex normals are bent far from their
// faces, as tree generators bend leaf cards' normals towards a sphere
// around the crown (about 60 degrees) for soft foliage shading. The
// smooth surface such normals describe is no surface at all: Hanika's lift
// (meant for finely tessellated closed meshes) would move a card's point
// further than the spacing between cards, past the card above it, which
// then no longer shadows it. The lift is the terminator model's
// (src/reference/terminator_offset.hpp): Cycles' envelope of the corners'
// tangent planes, only where the light grazes the surface, along the
// shading normal, the same vector in the traced reference and in the
// techniques' lookups. On the cards' pixels the techniques' mean shadow
// factor is that of the reference.
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>

#include "gpu_fixture.hpp"
#include "reference/traced_reference.hpp"
#include "render/renderer.hpp"
#include "scene/mesh.hpp"
#include "scene/model.hpp"
#include "test_scene.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

// The crown's centre, beside the stack: the normals lean away from it.
const glm::vec3 kCrown{0.5f, 1.1f, -0.3f};

// Eight horizontal cards 0.3 wide, 3.5 cm apart, each shifted a little
// from the one below, every corner's normal bent 60 degrees from the face
// towards the outside of the crown.
std::shared_ptr<Model> bent_card_stack() {
  auto model = std::make_shared<Model>();
  model->materials.push_back(
      Material{"leaf", glm::vec3(0.15f, 0.6f, 0.15f), glm::vec3(0.0f), 8.0f});
  const float bend = glm::radians(60.0f);
  for (int card = 0; card < 8; ++card) {
    const glm::vec3 centre{0.03f * static_cast<float>(card % 3) - 0.03f,
                           1.0f + 0.035f * static_cast<float>(card),
                           0.025f * static_cast<float>(card % 2)};
    const auto first = static_cast<std::uint32_t>(model->mesh.vertices.size());
    for (const glm::vec2 corner :
         {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      const glm::vec3 p = centre + 0.15f * glm::vec3(corner.x, 0.0f, corner.y);
      glm::vec3 out = p - kCrown;
      out.y = 0.0f;
      const glm::vec3 n =
          std::cos(bend) * glm::vec3(0.0f, 1.0f, 0.0f) + std::sin(bend) * glm::normalize(out);
      model->mesh.vertices.push_back(Vertex{p, n, 0});
    }
    for (const std::uint32_t k : {0u, 2u, 1u, 0u, 3u, 2u}) {
      model->mesh.indices.push_back(first + k);
    }
  }
  model->bounds = model->mesh.bounds();
  return model;
}

Scene card_stack_scene() {
  Shape cards;
  cards.kind = ShapeKind::Model;
  cards.model = bent_card_stack();
  return testing::TestScene("bent-normal cards", 0.6f)
      .ground(6.0f)
      .shape(cards)
      .camera({0.0f, 2.3f, 1.4f}, {0.0f, 1.1f, 0.0f}, 22.0f)
      .light(testing::spot_light({-0.9f, 3.0f, 0.6f}, {0.0f, 1.1f, 0.0f}, 30.0f, 25.0f));
}

// The technique's mean shadow factor minus the reference's over the
// cards' pixels the reference judges.
double card_mean_error(Renderer& renderer, const ShadowSettings& shadow, int* cards) {
  RenderSettings rs = testing::small_frame(160, 120);
  renderer.render(rs, shadow);
  const Image image = renderer.read_view();
  const TracedReference reference = traced_reference(renderer, rs, shadow, 256, "");
  const SurfacePoints surfaces = renderer.read_surfaces();
  double sum = 0.0, reference_sum = 0.0;
  *cards = 0;
  for (int y = 0; y < rs.height; ++y) {
    for (int x = 0; x < rs.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * rs.width + x;
      if (!surfaces.covered[i] || surfaces.position[i].y < 0.5f) continue;  // the ground
      if (reference.image.pixel(x, y)[3] == 0.0f || image.pixel(x, y)[3] == 0.0f) continue;
      ++*cards;
      sum += image.pixel(x, y)[0] - reference.image.pixel(x, y)[0];
      reference_sum += reference.image.pixel(x, y)[0];
    }
  }
  std::printf("reference's mean on the cards %.3f\n", reference_sum / std::max(*cards, 1));
  return sum / std::max(*cards, 1);
}

TEST_F(GpuTest, BentNormalCardsShadowTheCardsBehindThemAsTheReferenceDoes) {
  Renderer renderer(card_stack_scene());
  ShadowSettings hard;
  hard.technique = Technique::Hard;
  hard.light_size = 0.0f;
  ShadowSettings pcss;
  pcss.technique = Technique::Pcss;
  pcss.light_size = 0.3f;
  for (const auto& [name, shadow] : {std::pair{"hard", hard}, std::pair{"pcss", pcss}}) {
    int cards = 0;
    const double error = card_mean_error(renderer, shadow, &cards);
    std::printf("%s: %d card pixels, mean error %+.4f\n", name, cards, error);
    ASSERT_GT(cards, 2000);
    EXPECT_NEAR(error, 0.0, 0.03) << name;
  }
}

}  // namespace
}  // namespace penumbra
