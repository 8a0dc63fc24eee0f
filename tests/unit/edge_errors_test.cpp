// The report's account of the error at light size 0: pixels a binary
// shadow gets wrong, and how many of them sit at the reference's edges.
#include "report/edge_errors.hpp"

#include <gtest/gtest.h>

#include "penumbra/error.hpp"

namespace {

using penumbra::Image;

// A 20 x 8 shadow factor, 0 left of column `edge` and 1 from it on.
Image half_shadowed(int edge) {
  Image image(20, 8);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      float* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = x < edge ? 0.0f : 1.0f;
      p[3] = 1.0f;
    }
  }
  return image;
}

TEST(EdgeErrors, CountsWrongPixelsAndThoseAtTheReferencesEdge) {
  const Image reference = half_shadowed(10);
  Image technique = half_shadowed(11);  // the edge one pixel late
  technique.pixel(18, 4)[0] = 0.0f;     // and a dark speck far from it
  technique.pixel(2, 2)[0] = 0.4f;      // off by less than a half: not wrong
  technique.pixel(0, 0)[3] = 0.0f;      // not compared
  const penumbra::EdgeErrors e = penumbra::edge_errors(technique, reference, 2);
  EXPECT_EQ(e.compared, 20 * 8 - 1);
  EXPECT_EQ(e.wrong, 8 + 1);
  EXPECT_EQ(e.near_edge, 8);
  // A reach of 0 sees no edge.
  EXPECT_EQ(penumbra::edge_errors(technique, reference, 0).near_edge, 0);
}

TEST(EdgeErrors, ImagesOfDifferentSizesAreAnError) {
  EXPECT_THROW(penumbra::edge_errors(Image(4, 4), Image(4, 5), 1), penumbra::RuntimeError);
  EXPECT_THROW(penumbra::at_reference_edges(Image(4, 4), Image(4, 5), 1), penumbra::RuntimeError);
}

// Only the columns within the reach of the reference's edge stay compared.
TEST(EdgeErrors, AtReferenceEdgesKeepsThePixelsNearTheEdge) {
  const Image reference = half_shadowed(10);
  const Image edges = penumbra::at_reference_edges(half_shadowed(11), reference, 2);
  for (int x = 0; x < 20; ++x) {
    const bool near = x >= 8 && x <= 11;  // within 2 of the step between 9 and 10
    EXPECT_EQ(edges.pixel(x, 3)[3], near ? 1.0f : 0.0f) << x;
    EXPECT_EQ(edges.pixel(x, 3)[0], x < 11 ? 0.0f : 1.0f) << x;
  }
}

}  // namespace
