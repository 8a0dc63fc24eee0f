// The near and far halves of a view (compare's traced_near, traced_far)
// and the texel-density shares, on images whose answers are known by hand.
#include "reference/distance_halves.hpp"

#include <gtest/gtest.h>

#include "penumbra/error.hpp"
#include "reference/ground_pixels.hpp"
#include "reference/shadow_metrics.hpp"
#include "reference/texel_density_stats.hpp"

namespace penumbra {
namespace {

// A w x 1 row of surfaces at x = 1, 2, ... units in front of a camera at
// the origin (pixel x at distance x + 1), every pixel judged.
struct Row {
  SurfacePoints surfaces;
  Image judged;
  explicit Row(int w) : surfaces(w, 1), judged(w, 1) {
    for (int x = 0; x < w; ++x) {
      surfaces.position[static_cast<std::size_t>(x)] = {0.0f, 0.0f, -(x + 1.0f)};
      surfaces.covered[static_cast<std::size_t>(x)] = 1;
      judged.pixel(x, 0)[3] = 1.0f;
    }
  }
};

TEST(DistanceHalves, SplitAtTheMedianDistanceOfTheJudgedPixels) {
  Row row(6);
  row.judged.pixel(5, 0)[3] = 0.0f;  // the farthest is not judged: 5 pixels, median 3
  const DistanceHalves halves = split_at_median_distance(row.surfaces, {0, 0, 0}, row.judged);
  EXPECT_DOUBLE_EQ(halves.median_distance, 3.0);
  EXPECT_EQ(halves.near_pixels, 3);
  EXPECT_EQ(halves.far_pixels, 2);
  EXPECT_EQ(halves.far, (std::vector<std::uint8_t>{0, 0, 0, 1, 1, 0}));
}

TEST(DistanceHalves, EachHalfIsMeasuredOnItsOwnPixels) {
  Row row(4);
  Image reference = row.judged, technique = row.judged;
  for (int x = 0; x < 4; ++x) reference.pixel(x, 0)[0] = 1.0f;
  // Wrong only in the far half (distances 3 and 4): by 0.5 and 1.
  technique.pixel(0, 0)[0] = technique.pixel(1, 0)[0] = 1.0f;
  technique.pixel(2, 0)[0] = 0.5f;
  technique.pixel(3, 0)[0] = 0.0f;
  const DistanceHalves halves = split_at_median_distance(row.surfaces, {0, 0, 0}, reference);
  const ShadowMetrics near = compare_shadow(only_half(technique, halves, false), reference);
  const ShadowMetrics far = compare_shadow(only_half(technique, halves, true), reference);
  EXPECT_EQ(near.pixels, 2);
  EXPECT_EQ(near.rmse, 0.0);
  EXPECT_EQ(far.pixels, 2);
  EXPECT_DOUBLE_EQ(far.mean_absolute_error, 0.75);
}

TEST(DistanceHalves, SizesMustAgree) {
  Row row(4);
  EXPECT_THROW(split_at_median_distance(row.surfaces, {0, 0, 0}, Image(3, 1)), RuntimeError);
}

TEST(TexelDensityStats, SharesOverJudgedAndShadowedPixels) {
  // Densities 0.5, 1, 2, 4, 0 (no map); the reference shadows the first
  // two and does not judge the last.
  const float densities[] = {0.5f, 1.0f, 2.0f, 4.0f, 0.0f};
  Image density(5, 1), reference(5, 1);
  for (int x = 0; x < 5; ++x) {
    density.pixel(x, 0)[0] = densities[x];
    density.pixel(x, 0)[3] = 1.0f;
    reference.pixel(x, 0)[0] = x < 2 ? 0.2f : 1.0f;
    reference.pixel(x, 0)[3] = x < 4 ? 1.0f : 0.0f;
  }
  const TexelDensityStats s = texel_density_stats(density, reference);
  EXPECT_EQ(s.judged.pixels, 4);
  EXPECT_DOUBLE_EQ(s.judged.at_least_one, 0.75);
  EXPECT_DOUBLE_EQ(s.judged.median, 1.0);  // the lower median
  EXPECT_EQ(s.shadowed.pixels, 2);
  EXPECT_DOUBLE_EQ(s.shadowed.at_least_one, 0.5);
  const TexelDensityShare seen = texel_density_share(density);
  EXPECT_EQ(seen.pixels, 5);
  EXPECT_DOUBLE_EQ(seen.at_least_one, 0.6);
  EXPECT_THROW(texel_density_stats(density, Image(4, 1)), RuntimeError);
  EXPECT_EQ(s.shadowed_ground.pixels, 0) << "no ground given";

  // The second shadowed pixel and a lit one on the ground.
  const std::vector<std::uint8_t> ground = {0, 1, 1, 0, 0};
  const TexelDensityStats g = texel_density_stats(density, reference, ground);
  EXPECT_EQ(g.shadowed_ground.pixels, 1);
  EXPECT_DOUBLE_EQ(g.shadowed_ground.at_least_one, 1.0);
  EXPECT_THROW(texel_density_stats(density, reference, {1, 0}), RuntimeError);
}

// The ground's pixels: points on a plane shape (tilted and moved here),
// within its rectangle, with its normal; not a box's side standing on
// it, nor a point above it or past its edge.
TEST(GroundPixels, PointsOnAPlaneShapeWithItsNormal) {
  Scene scene;
  Shape plane;
  plane.kind = ShapeKind::Plane;
  plane.size = {10.0f, 0.0f, 4.0f};
  plane.position = {1.0f, 2.0f, 3.0f};
  plane.rotation_degrees = {0.0f, 0.0f, 30.0f};  // about z: the x side tilts up
  scene.shapes = {plane};
  const glm::vec3 up(-0.5f, std::sqrt(3.0f) / 2.0f, 0.0f);  // the plane's normal
  const glm::vec3 side(std::sqrt(3.0f) / 2.0f, 0.5f, 0.0f);
  const glm::vec3 centre = plane.position;
  SurfacePoints s(6, 1);
  const glm::vec3 positions[] = {centre + 4.0f * side,  // on it
                                 centre + 4.0f * side + 1.5f * glm::vec3(0, 0, 1),
                                 centre + 6.0f * side,  // past its edge
                                 centre + 0.01f * up,   // above it
                                 centre,                // a side standing on it
                                 centre};               // not covered
  const glm::vec3 normals[] = {up, -up, up, up, side, up};
  for (int i = 0; i < 6; ++i) {
    s.position[i] = positions[i];
    s.normal[i] = normals[i];
    s.covered[i] = i < 5 ? 1 : 0;
  }
  const std::vector<std::uint8_t> expected = {1, 1, 0, 0, 0, 0};
  EXPECT_EQ(ground_pixels(scene, s), expected);
}

}  // namespace
}  // namespace penumbra
