#pragma once
// "Did you mean ...?" for a mistyped command, option or name.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

// Edit distance with adjacent transpositions ("optimal string alignment"):
// the fewest insertions, deletions, substitutions and swaps of two
// neighbours that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate `typed` most likely meant: the nearest by edit distance
// when it is close enough (at most a third of the word, and at least 1),
// else the only candidate `typed` is a prefix of; nullopt if none is.
std::optional<std::string> closest_name(std::string_view typed,
                                        const std::vector<std::string>& candidates);

// "; did you mean 'x'?" for closest_name's answer, or "".
std::string did_you_mean(std::string_view typed, const std::vector<std::string>& candidates);

}  // namespace penumbra
