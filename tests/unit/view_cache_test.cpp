// Cached shadow maps (penumbra/shadow/view_cache.hpp): which views a frame
// draws again, and the box test that decides which views see a caster.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "penumbra/shadow/view_cache.hpp"

namespace penumbra {
namespace {

// A spot-like view from `eye` looking down -y at `target`.
ShadowViewData view_from(const glm::vec3& eye, const glm::vec3& target) {
  ShadowViewData v{};
  v.view = glm::lookAt(eye, target, glm::vec3(0.0f, 0.0f, -1.0f));
  v.view_projection = glm::perspective(glm::radians(40.0f), 1.0f, 0.5f, 20.0f) * v.view;
  v.depth_range = glm::vec4(0.5f, 20.0f, 0.01f, 64.0f);
  v.perspective = 1;
  return v;
}

CasterBounds box_at(const glm::vec3& centre, float half = 0.5f) {
  return {centre - glm::vec3(half), centre + glm::vec3(half)};
}

TEST(ViewCache, BoxTestFollowsTheFrustum) {
  const ShadowViewData v = view_from({0, 10, 0}, {0, 0, 0});
  EXPECT_TRUE(box_may_be_seen(v.view_projection, box_at({0, 0, 0})));
  // Just outside the 40-degree cone at the ground (tan 20 deg * 10 = 3.6).
  EXPECT_FALSE(box_may_be_seen(v.view_projection, box_at({5.0f, 0, 0})));
  EXPECT_FALSE(box_may_be_seen(v.view_projection, box_at({0, 0, -5.0f})));
  // Straddling the edge, and large enough to contain the whole frustum.
  EXPECT_TRUE(box_may_be_seen(v.view_projection, box_at({3.8f, 0, 0})));
  EXPECT_TRUE(box_may_be_seen(v.view_projection, box_at({0, 5, 0}, 50.0f)));
  // Behind the eye.
  EXPECT_FALSE(box_may_be_seen(v.view_projection, box_at({0, 14, 0})));
}

TEST(ViewCache, DrawsOnlyWhatChanged) {
  const std::vector<ShadowViewData> views = {view_from({0, 10, 0}, {0, 0, 0}),
                                             view_from({20, 10, 0}, {20, 0, 0})};
  ViewCache cache;
  using Flags = std::vector<std::uint8_t>;
  // The cache's flags, copied (they are valid until its next call).
  const auto stale = [&cache](std::span<const ShadowViewData> v, int map_size) {
    const std::span<const std::uint8_t> flags = cache.stale_views(v, map_size);
    return Flags(flags.begin(), flags.end());
  };
  EXPECT_EQ(stale(views, 64), (Flags{1, 1})) << "nothing drawn yet";
  EXPECT_EQ(stale(views, 64), (Flags{0, 0})) << "a static frame";

  // A caster moves under the second view only, then from the first view's
  // area into the second's: the views that see it before or after.
  cache.caster_moved(box_at({20, 0, 0}), box_at({21, 0, 0}));
  EXPECT_EQ(stale(views, 64), (Flags{0, 1}));
  cache.caster_moved(box_at({0, 0, 0}), box_at({20, 0, 0}));
  EXPECT_EQ(stale(views, 64), (Flags{1, 1}));
  cache.caster_moved(box_at({10, 0, 0}), box_at({10, 0, 1}));
  EXPECT_EQ(stale(views, 64), (Flags{0, 0})) << "seen by neither";

  // A view refitted (its depth range), the map size, the view count.
  std::vector<ShadowViewData> refitted = views;
  refitted[1].depth_range.y = 21.0f;
  EXPECT_EQ(stale(refitted, 64), (Flags{0, 1}));
  EXPECT_EQ(stale(refitted, 128), (Flags{1, 1}));
  EXPECT_EQ(stale(std::span(refitted).first(1), 128), (Flags{1}));

  // What only the lookup reads changes no depth.
  std::vector<ShadowViewData> wider = refitted;
  wider[0].source_width = 2.0f;
  EXPECT_EQ(stale(refitted, 128), (Flags{1, 1}));
  EXPECT_EQ(stale(wider, 128), (Flags{0, 0}));

  cache.invalidate();
  EXPECT_EQ(stale(wider, 128), (Flags{1, 1}));
}

}  // namespace
}  // namespace penumbra
