#include "options/cli_values.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace uvtk::cli {

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

CLI::Option* addOverlapResolutionOption(CLI::App& app, int& overlapResolution) {
  return app
      .add_option("--overlap-resolution", overlapResolution,
                  "Pixels across the raster that measures overlap; 0: sixteen a face, 256 to 1024")
      ->capture_default_str();
}

CLI::Option* addThreadsOption(CLI::App& app, int& threads, const std::string& help) {
  return app.add_option("--threads", threads, help)->check(CLI::Range(0, 1024))->default_str("0");
}

}  // namespace uvtk::cli
