// "Did you mean ...?" for names typed with a slip: commands, object ids.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apprentice {

// The candidate nearest to `word` (edit distance, ignoring case, a swap of
// two neighbouring letters counting as one edit) when it is near enough to
// be a slip: at most two edits, and fewer than half of the word's length.
// On a tie, the first candidate.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace apprentice
