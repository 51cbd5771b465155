#include "options/verdict_cli.h"

#include <cstdio>

#include "core/error.h"
#include "options/cli_values.h"

namespace uvtk::cli {

analysis::Thresholds VerdictArguments::thresholds() const {
  analysis::Thresholds t;
  for (const std::string& entry : failOn)
    if (!analysis::parseVerdict(entry)) t.set(entry, analysis::Verdict::Fail, "--fail-on");
  for (const std::string& entry : warnOn) t.set(entry, analysis::Verdict::Warn, "--warn-on");
  return t;
}

std::optional<analysis::Verdict> VerdictArguments::exitFrom() const {
  std::optional<analysis::Verdict> from;
  for (const std::string& entry : failOn) {
    const std::optional<analysis::Verdict> v = analysis::parseVerdict(entry);
    if (!v) continue;
    if (*v == analysis::Verdict::Pass) throw UsageError("--fail-on: expected warn or fail, found pass");
    if (from && *from != *v) throw UsageError("--fail-on: give warn or fail once");
    from = v;
  }
  return from;
}

void addVerdictOptions(CLI::App& app, VerdictArguments& a) {
  app.add_option("--fail-on", a.failOn,
                 "warn|fail: exit 1 when the verdict is at least that bad; RULE=VALUE: fail when the rule's value "
                 "exceeds VALUE (off: never); repeatable (docs/conventions.md §11)")
      ->take_all()
      ->delimiter(',');
  app.add_option("--warn-on", a.warnOn, "RULE=VALUE: warn when the rule's value exceeds VALUE (off: never); repeatable")
      ->take_all()
      ->delimiter(',');
}

void addMapThreadsOption(CLI::App& app, int& threads) {
  addThreadsOption(app, threads,
                   "Threads each mesh is read, mapped, judged and written with; 0: one per hardware thread for one "
                   "mesh, one per mesh of many");
}

void addMapJudgementOptions(CLI::App& app, int& overlapResolution, std::string& textureSize,
                            std::optional<double>& density) {
  addOverlapResolutionOption(app, overlapResolution);
  app.add_option("--texture-size", textureSize, "Texels W,H (or N: N,N) of the texture that texel density counts in")
      ->capture_default_str();
  app.add_option("--density", density,
                 "Scale the UVs about (0, 0) so that the mean texel density is this many texels per object unit");
}

void enforceVerdict(const VerdictArguments& a, analysis::Verdict verdict, const std::string& what) {
  const std::optional<analysis::Verdict> from = a.exitFrom();
  if (!from || verdict < *from) return;
  const std::string message =
      what + ": the verdict is " + analysis::toString(verdict) + " (--fail-on " + analysis::toString(*from) + "): exit 1";
  std::fprintf(stderr, "%s\n", message.c_str());  // main prints nothing for a CheckFailure
  throw CheckFailure(message);
}

}  // namespace uvtk::cli
