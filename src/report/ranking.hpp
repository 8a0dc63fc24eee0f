#pragma once
// Choosing winners from measured numbers the way the page prints them: a
// difference the page cannot show is a tie, not a win.
#include <string>
#include <vector>

namespace penumbra {

struct CostQuality {
  double cost = 0.0;   // e.g. GPU time, lower is better
  double error = 0.0;  // e.g. RMSE, lower is better
};

// Indices of the points no other point dominates (another is at least as
// good in both and better in one): the Pareto front of cost against error,
// in the order given.
std::vector<std::size_t> pareto_front(const std::vector<CostQuality>& points);

// Indices of the values that, written with `digits` decimals, equal the
// least written value: every one of them is a winner (ties stay ties).
std::vector<std::size_t> least_at_precision(const std::vector<double>& values, int digits);

// "a", "a and b", "a, b and c".
std::string join_names(const std::vector<std::string>& names);

}  // namespace penumbra
