// Winners as the report prints them: ties at the printed precision, and the
// Pareto front of cost against error.
#include "report/ranking.hpp"

#include <gtest/gtest.h>

namespace {

using penumbra::least_at_precision;

TEST(Ranking, ValuesEqualAtThePrintedPrecisionAllWin) {
  // The ESM sweep's case: 0.00104, 0.00096 and 0.00100 all print 0.0010.
  const std::vector<double> mae = {0.0031, 0.0017, 0.00104, 0.00096, 0.00100, 0.0012};
  EXPECT_EQ(least_at_precision(mae, 4), (std::vector<std::size_t>{2, 3, 4}));
  EXPECT_EQ(least_at_precision(mae, 5), (std::vector<std::size_t>{3}));
  EXPECT_EQ(least_at_precision({0.5}, 2), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(least_at_precision({}, 2).empty());
}

TEST(Ranking, ParetoFrontKeepsWhatNothingBeatsInBoth) {
  const std::vector<penumbra::CostQuality> points = {
      {1.0, 0.10},  // cheapest
      {2.0, 0.05},  // better and dearer: on the front
      {2.5, 0.08},  // beaten by the one before in both
      {4.0, 0.05},  // as good, dearer: dominated
      {5.0, 0.01},  // best
      {1.0, 0.10},  // a duplicate dominates nothing and is not dominated
  };
  EXPECT_EQ(penumbra::pareto_front(points), (std::vector<std::size_t>{0, 1, 4, 5}));
}

TEST(Ranking, JoinNames) {
  EXPECT_EQ(penumbra::join_names({"a"}), "a");
  EXPECT_EQ(penumbra::join_names({"a", "b"}), "a and b");
  EXPECT_EQ(penumbra::join_names({"c = 60", "80", "87"}), "c = 60, 80 and 87");
}

}  // namespace
