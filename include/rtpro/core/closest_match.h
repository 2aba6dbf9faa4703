#pragma once
// "Did you mean" for every name a user types: scene keys and types, subcommands, options.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// Names longer than this are never typos of one another worth a suggestion: skipping them keeps
// the cost of a suggestion bounded whatever a file names things (a 30,000-character name took
// gigabytes).
inline constexpr std::size_t kMaxSuggestedLength = 64;

// The candidate nearest to `word` by edit distance, if near enough to be a likely typo; nothing
// for a word or candidate longer than kMaxSuggestedLength.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);
// "; did you mean 'radius'?", or "; expected one of: a, b, c" when nothing is near.
std::string suggestion(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace rtpro
