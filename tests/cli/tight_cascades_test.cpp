// --tight-cascades end to end: the sun's cascades fitted to what the view
// sees put about twice the texels on each pixel of the default scene, and
// the hard and soft shadows read them closer to the traced reference.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_run.hpp"

namespace {

using penumbra::testing::out_path;
using penumbra::testing::Result;
using penumbra::testing::run;

nlohmann::json compare_sun(const std::string& name, const std::string& options) {
  const std::string json_path = out_path("tight-cascades-" + name + ".json");
  const Result r =
      run("compare --scene default --light directional --technique hard,pcss --width 320 "
          "--height 180 --shadow-map-size 512 --reference-samples 64 --cache-dir " +
          out_path("tight-cascades-cache") + " --json " + json_path + options);
  EXPECT_EQ(r.status, 0) << r.err;
  std::ifstream in(json_path);
  return nlohmann::json::parse(in);
}

TEST(TightCascades, MoreTexelsOnEveryPixelAndLessErrorUnderTheSun) {
  const nlohmann::json stable = compare_sun("stable", "");
  const nlohmann::json tight = compare_sun("tight", " --tight-cascades");
  EXPECT_FALSE(stable["tight_cascades"].get<bool>());
  EXPECT_TRUE(tight["tight_cascades"].get<bool>());
  const double stable_density = stable["texel_density"]["judged"]["median"].get<double>();
  const double tight_density = tight["texel_density"]["judged"]["median"].get<double>();
  // An area ratio: squares 1.4 times narrower give about 2 times the texels.
  EXPECT_GT(tight_density, 1.6 * stable_density);
  ASSERT_EQ(stable["results"].size(), 2u);
  ASSERT_EQ(tight["results"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string technique = stable["results"][i]["technique"].get<std::string>();
    EXPECT_LT(tight["results"][i]["traced"]["rmse"].get<double>(),
              0.9 * stable["results"][i]["traced"]["rmse"].get<double>())
        << technique;
  }
}

}  // namespace
