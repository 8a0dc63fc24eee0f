#include "penumbra/filter/gaussian.hpp"

#include <cmath>

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

}  // namespace penumbra
