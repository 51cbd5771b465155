// The verdict's options shared by `uvtk map`, `report` and `check`: thresholds (--fail-on
// RULE=VALUE, --warn-on RULE=VALUE) and the exit status for CI (--fail-on warn|fail).
// docs/conventions.md §11.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.h"

namespace uvtk::cli {

struct VerdictArguments {
  std::vector<std::string> failOn, warnOn;

  // The default thresholds with every RULE=VALUE given. Throws UsageError for a bad entry.
  analysis::Thresholds thresholds() const;
  // The verdict from which the command exits 1 (--fail-on warn or fail); none by default.
  std::optional<analysis::Verdict> exitFrom() const;
  void check() const { thresholds(), exitFrom(); }  // throws UsageError before any work
};
void addVerdictOptions(CLI::App& app, VerdictArguments& arguments);

// `uvtk map`'s --threads, and its judgement's --overlap-resolution, --texture-size and --density:
// the command and the library's MapOptions (whose describe() gives Python's signatures) add the
// same options with the same help.
void addMapThreadsOption(CLI::App& app, int& threads);
void addMapJudgementOptions(CLI::App& app, int& overlapResolution, std::string& textureSize,
                            std::optional<double>& density);

// Throws CheckFailure (exit 1) with `what` and the verdict's line when --fail-on names a verdict
// that `verdict` reaches; the command has written its outputs before.
void enforceVerdict(const VerdictArguments& arguments, analysis::Verdict verdict, const std::string& what);

}  // namespace uvtk::cli
