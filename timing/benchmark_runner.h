// Google Benchmark behind a plugin: `uvtk bench` times its configurations through it, and no other
// command loads libbenchmark (linked, it cost every process 0.19 ms at start: docs/benchmarks.md,
// "Start-up"). This header is the whole interface between the program and the plugin.
#pragma once

#include <functional>
#include <string>
#include <vector>

#define UVTK_BENCHMARK_RUNNER_ENTRY "uvtk_benchmark_runner"

namespace uvtk::timing::runner {

constexpr int kVersion = 1;

// One configuration timed: `iteration` does the work once and returns the address of its result,
// which Google Benchmark keeps from being optimised away.
struct TimedCase {
  std::string name;
  std::function<const void*()> iteration;
  double minTime = 0.3;  // seconds of wall time, at least
};

struct Functions {
  int version;
  // The seconds of wall time per iteration of each case, in order (Google Benchmark's real time).
  // Throws std::logic_error for a case that did not run.
  std::vector<double> (*run)(const std::vector<TimedCase>& cases);
};

}  // namespace uvtk::timing::runner
