#include "report/ranking.hpp"

#include <cstdio>
#include <cstdlib>

namespace penumbra {

std::vector<std::size_t> pareto_front(const std::vector<CostQuality>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      const CostQuality& a = points[j];
      const CostQuality& b = points[i];
      dominated = j != i && a.cost <= b.cost && a.error <= b.error &&
                  (a.cost < b.cost || a.error < b.error);
    }
    if (!dominated) front.push_back(i);
  }
  return front;
}

std::vector<std::size_t> least_at_precision(const std::vector<double>& values, int digits) {
  // Compare the values as the page writes them (printf's rounding).
  std::vector<double> rounded;
  for (double v : values) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, v);
    rounded.push_back(std::strtod(text, nullptr));
  }
  std::vector<std::size_t> least;
  for (std::size_t i = 0; i < rounded.size(); ++i) {
    if (!least.empty() && rounded[i] > rounded[least.front()]) continue;
    if (!least.empty() && rounded[i] < rounded[least.front()]) least.clear();
    least.push_back(i);
  }
  return least;
}

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " and " : ", ";
    out += names[i];
  }
  return out;
}

}  // namespace penumbra
