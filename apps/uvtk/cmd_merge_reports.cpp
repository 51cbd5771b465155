// `uvtk merge-reports`: the JSON reports of many independent runs merged into one file with
// totals (inspect/merge_reports.h, docs/scale-out.md).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/progress.h"
#include "inspect/merge_reports.h"

namespace uvtk::cli {

namespace {

struct MergeArguments {
  std::string output;
  std::vector<std::string> inputs;
};

}  // namespace

void addMergeReportsCommand(CLI::App& root) {
  auto arguments = std::make_shared<MergeArguments>();
  CLI::App* merge = root.add_subcommand(
      "merge-reports", "Merge the JSON reports of many runs (files, or folders of *.json) into one, with totals");
  merge->add_option("inputs", arguments->inputs, "Report files, or folders whose *.json files (recursively) are merged")
      ->required();
  merge->add_option("-o,--output", arguments->output, "The merged JSON report")->required();
  merge->callback([arguments] {
    const std::string line = inspect::mergeReports(arguments->inputs, arguments->output);
    if (!quiet()) std::cout << "uvtk merge-reports: " << line << "\n";
  });
}

}  // namespace uvtk::cli
