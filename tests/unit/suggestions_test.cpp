// "Did you mean": the edit distance against hand-counted cases, and which
// name is suggested (or none).
#include "app/suggestions.hpp"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

TEST(Suggestions, EditDistanceCountsEachKindOfEdit) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("render", "render"), 0u);
  EXPECT_EQ(edit_distance("rendr", "render"), 1u);    // an insertion
  EXPECT_EQ(edit_distance("renderr", "render"), 1u);  // a deletion
  EXPECT_EQ(edit_distance("pfc", "pcf"), 1u);         // a swap of neighbours
  EXPECT_EQ(edit_distance("vsn", "vsm"), 1u);         // a substitution
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("--techniqe", "--technique"), 1u);
}

TEST(Suggestions, TheNearestCloseNameOrAUniquePrefix) {
  const std::vector<std::string> commands = {"render", "view", "compare", "bench", "report"};
  EXPECT_EQ(closest_name("rendr", commands), "render");
  EXPECT_EQ(closest_name("comapre", commands), "compare");
  EXPECT_EQ(closest_name("bnech", commands), "bench");
  EXPECT_EQ(closest_name("frobnicate", commands), std::nullopt);
  EXPECT_EQ(closest_name("x", commands), std::nullopt);
  const std::vector<std::string> options = {"--technique", "--filter", "--blur",
                                            "--shadow-map-size"};
  EXPECT_EQ(closest_name("--techniqe", options), "--technique");
  EXPECT_EQ(closest_name("--blurr", options), "--blur");
  // Dashes do not count towards how far a word may be off.
  EXPECT_EQ(closest_name("--x", options), std::nullopt);
  // A prefix of exactly one name.
  EXPECT_EQ(closest_name("--shadow", options), "--shadow-map-size");
  EXPECT_EQ(did_you_mean("--filtre", options), "; did you mean '--filter'?");
  EXPECT_EQ(did_you_mean("--bogus", options), "");
}

}  // namespace
}  // namespace penumbra
