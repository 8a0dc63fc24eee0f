#include "penumbra/filter/gaussian.hpp"

#include <cmath>
#include <cstdio>

namespace penumbra {

std::vector<float> gaussian_weights(int w) {
  if (w <= 0) return {1.0f};
  const double s = w / 2.0;
  std::vector<double> weights(2 * w + 1);
  double sum = 0.0;
  for (int i = -w; i <= w; ++i) {
    weights[i + w] = std::exp(-double(i) * i / (2.0 * s * s));
    sum += weights[i + w];
  }
  std::vector<float> result(weights.size());
  for (std::size_t k = 0; k < weights.size(); ++k) result[k] = float(weights[k] / sum);
  return result;
}

std::string gaussian_weight_list(int w) {
  std::string list;
  for (float weight : gaussian_weights(w)) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%.9g", list.empty() ? "" : ", ", weight);
    list += text;
  }
  return list;
}

}  // namespace penumbra
