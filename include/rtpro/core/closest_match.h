#pragma once
// "Did you mean" for every name a user types: scene keys and types, subcommands, options.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro {

// The candidate nearest to `word` by edit distance, if near enough to be a likely typo.
std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates);
// "; did you mean 'radius'?", or "; expected one of: a, b, c" when nothing is near.
std::string suggestion(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace rtpro
