#include "rtpro/core/closest_match.h"

#include <algorithm>
#include <array>
#include <vector>

namespace rtpro {

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

// Optimal string alignment distance: insertions, deletions, substitutions and adjacent swaps
// ("resolutoin") each cost one; case is ignored. Three rows of the table (a swap looks two rows
// back), so the memory is linear in the candidate's length, never the product of both lengths.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::array<std::vector<std::size_t>, 3> rows;
  for (auto& row : rows) row.resize(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) rows[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::vector<std::size_t>& before = rows[(i + 1) % 3];  // row i - 2
    const std::vector<std::size_t>& above = rows[(i - 1) % 3];
    std::vector<std::size_t>& row = rows[i % 3];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({above[j] + 1, row[j - 1] + 1, above[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
  }
  return rows[a.size() % 3][b.size()];
}

std::size_t length_difference(std::string_view a, std::string_view b) {
  return a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
}

}  // namespace

std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  if (word.size() > kMaxSuggestedLength) return std::nullopt;
  const std::size_t tolerance = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> best;
  std::size_t best_distance = tolerance + 1;
  for (const std::string& candidate : candidates) {
    // The distance is at least the difference in length: such a candidate cannot be near.
    if (candidate.size() > kMaxSuggestedLength || length_difference(word, candidate) >= best_distance) continue;
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

std::string suggestion(std::string_view word, const std::vector<std::string>& candidates) {
  if (const auto near = closest_match(word, candidates)) return "; did you mean '" + *near + "'?";
  if (candidates.empty()) return "";
  constexpr std::size_t kListed = 12;
  std::string text = "; expected one of: ";
  for (std::size_t i = 0; i < std::min(kListed, candidates.size()); ++i) {
    const std::string& name = candidates[i];
    text += (i ? ", " : "") + (name.size() > kMaxSuggestedLength ? name.substr(0, kMaxSuggestedLength) + "..." : name);
  }
  if (candidates.size() > kListed) text += ", ... (" + std::to_string(candidates.size()) + " in all)";
  return text;
}

}  // namespace rtpro
