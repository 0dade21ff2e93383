#pragma once
/// @file
/// "Did you mean": the known name closest to a misspelt one, for errors about unknown keys,
/// flags and names.

#include <optional>
#include <string>
#include <vector>

namespace ceilplan {

/// The candidate nearest to `word` by edit distance (insertions, deletions, substitutions and
/// swaps of neighbours, case-insensitive, '-' and '_' alike), if it is close enough to be a
/// plausible slip: at most a third of the longer word's letters, and at least one letter.
std::optional<std::string> closestMatch(const std::string& word, const std::vector<std::string>& candidates);

/// "; did you mean 'x'?" when a close match exists, else "" (for appending to a message).
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace ceilplan
