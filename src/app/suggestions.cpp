#include "app/suggestions.hpp"

#include <algorithm>
#include <cctype>

namespace penumbra {

namespace {

std::string lowercase(std::string_view word) {
  std::string out(word);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // d[i][j]: distance between the first i characters of a and the first j of b.
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& candidates) {
  // Leading dashes are not part of the word: "--x" is as far from "--y"
  // as "x" from "y".
  const std::size_t dashes = std::min(typed.find_first_not_of('-'), typed.size());
  const std::size_t allowed = std::max<std::size_t>(1, (typed.size() - dashes) / 3);
  // Case does not count: names parse without regard to it ("PCSS").
  const std::string lower_typed = lowercase(typed);
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(lower_typed, lowercase(candidate));
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  if (best || typed.size() <= dashes) return best;
  std::vector<std::string> extensions;
  for (const std::string& candidate : candidates) {
    if (candidate.size() > typed.size() &&
        lowercase(candidate).compare(0, typed.size(), lower_typed) == 0) {
      extensions.push_back(candidate);
    }
  }
  if (extensions.size() == 1) return extensions.front();
  return std::nullopt;
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates) {
  const std::optional<std::string> name = closest_name(typed, candidates);
  return name ? "; did you mean '" + *name + "'?" : std::string();
}

}  // namespace penumbra
