// Virtual shadow maps against cascades on scenes/far_ground.json (a ground
// 400 units wide, the default objects, an alpha-tested tree 70 units
// away), at the same memory (a 48 MiB page pool, 3 cascades of 2048^2),
// as the README's table measures them, on a small view: at least one
// shadow-map texel per pixel on 95 % of the shadowed ground, and a lower
// error against the traced reference on the far half of the view.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;

nlohmann::json compare_far_ground(const std::string& layout) {
  const std::string json_path = out_path("virtual-far-ground-" + layout + ".json");
  // 320 x 180 puts the clipmap's level boundaries where 1280 x 720 does
  // (a quarter of the pixels: two levels coarser, the same distances).
  const Result r = run("compare --scene " + std::string(PENUMBRA_SOURCE_DIR) +
                       "/scenes/far_ground.json --technique hard,pcf --sun-angle 0 --width 320 "
                       "--height 180 --shadow-maps " +
                       layout + " --page-pool-mib 48 --cache-dir " +
                       out_path("virtual-far-ground-cache") + " --json " + json_path);
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(json_path);
  return nlohmann::json::parse(in);
}

TEST(VirtualFarGround, OneTexelPerPixelOnTheShadowedGroundAndLessErrorFarAway) {
  const nlohmann::json virtual_maps = compare_far_ground("virtual");
  const nlohmann::json cascades = compare_far_ground("cascades");
  const auto& ground = virtual_maps["texel_density"]["shadowed_ground"];
  ASSERT_GT(ground["pixels"].get<long>(), 200) << "the objects' shadows on the ground";
  EXPECT_GE(ground["at_least_one"].get<double>(), 0.95);
  EXPECT_LT(cascades["texel_density"]["shadowed_ground"]["at_least_one"].get<double>(),
            ground["at_least_one"].get<double>());
  ASSERT_EQ(virtual_maps["results"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& v = virtual_maps["results"][i];
    const auto& c = cascades["results"][i];
    const std::string technique = v["technique"].get<std::string>();
    EXPECT_LT(v["traced_far"]["rmse"].get<double>(), c["traced_far"]["rmse"].get<double>())
        << technique;
    const auto& pages = v["virtual_pages"];
    EXPECT_EQ(pages["pool"].get<int>(), 48 * 16) << "64 KiB pages";
    EXPECT_GT(pages["resident"].get<int>(), 0);
    EXPECT_LE(pages["resident"].get<int>(), pages["pool"].get<int>());
    EXPECT_EQ(pages["unserved"].get<int>(), 0) << technique;
    EXPECT_TRUE(c["virtual_pages"].is_null());
  }
}

}  // namespace
