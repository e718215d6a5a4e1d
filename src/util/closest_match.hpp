#pragma once
// "Did you mean ...?" for misspelled names: the candidate with the smallest edit distance.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bagnold {

// Levenshtein distance (insertions, deletions, substitutions), case-insensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate, if it is close enough to be a plausible misspelling
// (distance at most max(2, |word|/3)).
std::optional<std::string> closest_match(std::string_view word,
                                         const std::vector<std::string>& candidates);

// "a, b, c"
std::string join(const std::vector<std::string>& items, std::string_view separator = ", ");

}  // namespace bagnold
