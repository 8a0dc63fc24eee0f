#pragma once
// Numbers as the tables, verdicts and messages print them.
#include <string>

namespace penumbra {

// `value` with `digits` digits after the decimal point ("0.0123").
std::string fixed(double value, int digits);

}  // namespace penumbra
