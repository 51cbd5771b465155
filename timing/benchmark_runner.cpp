// The benchmark plugin (timing/benchmark_runner.h): Google Benchmark runs the cases it is given.
#include "timing/benchmark_runner.h"

#include <benchmark/benchmark.h>

#include <stdexcept>
#include <utility>

namespace uvtk::timing::runner {
namespace {

// Collects Google Benchmark's runs: seconds of wall time per iteration, by benchmark name.
class CollectingReporter : public benchmark::BenchmarkReporter {
 public:
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs)
      if (!run.error_occurred && run.iterations > 0)
        seconds_.emplace_back(run.benchmark_name(), run.real_accumulated_time / double(run.iterations));
  }
  // Google Benchmark appends the run's settings to the name ("map/3/min_time:0.300/real_time").
  double secondsOf(const std::string& name) const {
    for (const auto& [n, s] : seconds_)
      if (n == name || n.rfind(name + "/", 0) == 0) return s;
    throw std::logic_error("benchmark " + name + " did not run");
  }

 private:
  std::vector<std::pair<std::string, double>> seconds_;
};

std::vector<double> run(const std::vector<TimedCase>& cases) {
  static const bool initialized = [] {
    char* argv0 = const_cast<char*>("uvtk bench");
    int argc = 1;
    benchmark::Initialize(&argc, &argv0);
    return true;
  }();
  (void)initialized;
  for (const TimedCase& c : cases)
    benchmark::RegisterBenchmark(c.name.c_str(),
                                 [&c](benchmark::State& state) {
                                   for (auto _ : state) benchmark::DoNotOptimize(c.iteration());
                                 })
        ->MinTime(c.minTime)
        ->UseRealTime();
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::ClearRegisteredBenchmarks();
  std::vector<double> seconds;
  for (const TimedCase& c : cases) seconds.push_back(reporter.secondsOf(c.name));
  return seconds;
}

const Functions kFunctions{kVersion, run};

}  // namespace
}  // namespace uvtk::timing::runner

extern "C" __attribute__((visibility("default"))) const uvtk::timing::runner::Functions* uvtk_benchmark_runner() {
  return &uvtk::timing::runner::kFunctions;
}
