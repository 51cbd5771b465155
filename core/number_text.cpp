#include "core/number_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace uvtk {

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
  const bool square = text.find_first_of("xX") == std::string::npos;  // N: N x N, as --texture-size N
  if (square ? !(in >> w) || (in >> extra) || (h = w, false)
             : !(in >> w >> x >> h) || (x != 'x' && x != 'X') || bool(in >> extra))
    w = 0;
  if (w < 1 || h < 1 || w > 16384 || h > 16384)
    throw UsageError(option + ": expected WxH or N (NxN) with 1 <= W, H <= 16384, found '" + text + "'");
  return {w, h};
}

std::pair<int, int> parseTextureSize(const std::string& text, const std::string& option) {
  struct {
    int width = 0, height = 0;
  } size;
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
  return {size.width, size.height};
}

}  // namespace uvtk
