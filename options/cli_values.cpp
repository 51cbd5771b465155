#include "options/cli_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace uvtk::cli {

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

CLI::Option* addThreadsOption(CLI::App& app, int& threads, const std::string& help) {
  return app.add_option("--threads", threads, help)->check(CLI::Range(0, 1024))->default_str("0");
}

}  // namespace uvtk::cli
