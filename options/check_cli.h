// The options of `uvtk check` as typed, and the comparison they ask for (inspect/check.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "inspect/check.h"
#include "options/mapping_options.h"
#include "options/verdict_cli.h"

namespace uvtk::cli {

struct CheckArguments {
  std::string input, against, json, view;
  std::string viewSize = "512x512", viewDir = "0,0,1", viewUp = "0,1,0";
  std::string wrap = "none";
  std::optional<double> tolerance;
  int textureSize = 1024;
  int worst = 10;
  bool partial = false;
  MappingArguments mapping;
  std::vector<std::string> mappingOptions;  // every option addMappingOptions added
  VerdictArguments verdict;                 // of the stored UVs as a layout (docs/conventions.md §11)

  // The comparison, every option checked first (UsageError) so that nothing is read or written for
  // a bad command line: a mapping option with --against, --wrap without it, --seam cut.
  inspect::CheckOptions resolve() const;
};

}  // namespace uvtk::cli
