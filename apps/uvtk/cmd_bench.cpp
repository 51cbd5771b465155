// `uvtk bench`: the speed-accuracy trade measured in one run on the same data: mapping, rendering
// (--render) and the peers; a Markdown table, JSON records, Pareto charts and an HTML page
// (timing/bench.h, docs/precision.md).
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "options/bench_cli.h"

namespace uvtk::cli {

namespace {

void runBench(const BenchArguments& a) {
  const std::string md = timing::bench(a.resolve());
  if (a.markdown.empty()) std::fputs(md.c_str(), stdout);
}

}  // namespace

void addBenchCommand(CLI::App& root) {
  auto a = std::make_shared<BenchArguments>();
  CLI::App* cmd = root.add_subcommand("bench", "Measure speed against accuracy: mapping, rendering, and the peers");
  addBenchOptions(*cmd, *a);
  cmd->callback([a] { runBench(*a); });
}

}  // namespace uvtk::cli
