#include "core/number_text.hpp"

#include <cstdio>

namespace penumbra {

std::string fixed(double value, int digits) {
  char text[352];  // the widest double printed in full, "%.*f" with up to 16 digits
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace penumbra
