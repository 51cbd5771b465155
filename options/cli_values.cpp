#include "options/cli_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace uvtk::cli {

namespace {

Eigen::VectorXd parseSeparated(const std::string& text, int n, const std::string& option, const char* separators,
                               const std::string& expected) {
  Eigen::VectorXd values(n);
  const char* p = text.c_str();
  for (int i = 0; i < n; ++i) {
    while (*p == ' ' || (i > 0 && std::strchr(separators, *p) && *p != '\0')) ++p;
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(p, &end);
    if (end == p || errno == ERANGE || !std::isfinite(value))
      throw UsageError(option + ": expected " + expected + ", found '" + text + "'");
    values[i] = value;
    p = end;
  }
  while (*p == ' ') ++p;
  if (*p != '\0') throw UsageError(option + ": expected " + expected + ", found '" + text + "'");
  return values;
}

}  // namespace

Eigen::VectorXd parseNumbers(const std::string& text, int n, const std::string& option) {
  return parseSeparated(text, n, option, ",", std::to_string(n) + " comma-separated finite numbers");
}

Mat4 parseMatrix(const std::string& text, const std::string& option) {
  const Eigen::VectorXd v = parseSeparated(text, 16, option, ", ", "16 finite numbers (column-major)");
  return Eigen::Map<const Mat4>(v.data());  // Eigen's default storage is column-major, as GL's
}

std::pair<int, int> parseImageSize(const std::string& text, const std::string& option) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw UsageError(option + ": expected WxH with 1 <= W, H <= 16384, found '" + text + "'");
  return {w, h};
}

void checkDensity(double density) {
  if (density > 0.0 && std::isfinite(density)) return;
  char found[32];
  std::snprintf(found, sizeof found, "%g", density);
  throw UsageError(std::string("--density: expected a positive number of texels per object unit, found ") + found);
}

analysis::TextureSize parseTextureSize(const std::string& text, const std::string& option) {
  analysis::TextureSize size;
  char comma = 0, extra = 0;
  std::istringstream in(text);
  bool ok = bool(in >> size.width);
  if (ok && in >> comma) {
    ok = comma == ',' && in >> size.height && !(in >> extra);
  } else {
    size.height = size.width;
  }
  // Digits only: istream would also read "+5" or " 5".
  ok = ok && text.find_first_not_of("0123456789,") == std::string::npos;
  if (!ok || size.width < 1 || size.height < 1 || size.width > 16384 || size.height > 16384)
    throw UsageError(option + ": expected W,H or N (N,N) texels with 1 <= W, H <= 16384, found '" + text + "'");
  return size;
}

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

std::string nearestName(const std::string& typed, const std::vector<std::string>& names) {
  const std::string key = CLI::detail::to_lower(typed);
  std::string nearest, onlyPrefixed;
  std::size_t best = 0, prefixed = 0;
  for (const std::string& name : names) {
    const std::string candidate = CLI::detail::to_lower(name);
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
  return "'" + typed + "' is not one of: " + CLI::detail::join(names, ", ") +
         (nearest.empty() ? "" : "; did you mean '" + nearest + "'?");
}

CLI::Validator nameCheck(std::vector<std::string> names) {
  return CLI::Validator(
      [names = std::move(names)](const std::string& text) {
        return std::find(names.begin(), names.end(), text) != names.end() ? std::string() : notOneOf(text, names);
      },
      "");
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) items.push_back(item);
  return items;
}

}  // namespace uvtk::cli
