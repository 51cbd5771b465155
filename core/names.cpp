#include "core/names.h"

#include <algorithm>
#include <cctype>

namespace uvtk {

namespace {

// The optimal string alignment distance (Damerau-Levenshtein without editing a substring twice):
// insertions, deletions, substitutions and swaps of neighbours, each 1.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string lowerCase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string nearestName(const std::string& typed, const std::vector<std::string>& names) {
  const std::string key = lowerCase(typed);
  std::string nearest, onlyPrefixed;
  std::size_t best = 0, prefixed = 0;
  for (const std::string& name : names) {
    const std::string candidate = lowerCase(name);
    const std::size_t distance = editDistance(key, candidate);
    if (3 * distance <= std::max(key.size(), candidate.size()) && (nearest.empty() || distance < best)) {
      nearest = name;
      best = distance;
    }
    if (key.size() >= 3 && candidate.compare(0, key.size(), key) == 0) {
      onlyPrefixed = name;
      ++prefixed;
    }
  }
  if (!nearest.empty()) return nearest;
  return prefixed == 1 ? onlyPrefixed : "";
}

std::string notOneOf(const std::string& typed, const std::vector<std::string>& names) {
  const std::string nearest = nearestName(typed, names);
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return "'" + typed + "' is not one of: " + list + (nearest.empty() ? "" : "; did you mean '" + nearest + "'?");
}

}  // namespace uvtk
