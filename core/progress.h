// Progress of long counted work on stderr: a bar redrawn in place on a terminal, sparse plain
// lines in logs, nothing at all unless the program asked for it (a library prints nothing).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace uvtk {

// Whether progress is shown at all: off by default; the uvtk program turns it on unless --quiet.
void setProgressEnabled(bool enabled);
bool progressEnabled();

// Whether the user asked for quiet (uvtk's -q): commands then print no summary lines (errors and
// verdicts they exist to print still go out). Off by default; it does not touch progress.
void setQuiet(bool quiet);
bool quiet();

// Progress of counted work. On a terminal (isatty(stderr)), once the work has lasted 0.1 s, a bar
// redrawn in place at most 10 times a second, "LABEL [#########.........] 1234/5000 UNIT  2.3 s",
// cleared by finish().
// Otherwise plain lines, one at most every 5 seconds and only once the work has lasted 5 s
// ("LABEL: 1234/5000 UNIT, 5.0 s"), and a last one by finish() if any was printed: short runs
// print nothing in logs.
//
// Only one Progress is shown at a time: the first alive owns the display and any created while it
// lives stay silent, so the stages of a mesh inside `uvtk map DIR` do not fight the bar over meshes.
// advance() is thread-safe and cheap (an atomic add and a clock read; printing only when due):
// call it per block, tile or chunk, not per element.
class Progress {
 public:
  // `unitSize` counts make one displayed unit, shown with one decimal (bytes as MB: 1000000).
  Progress(std::string label, std::uint64_t total, std::string unit, std::uint64_t unitSize = 1);
  ~Progress();  // finish()
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void advance(std::uint64_t count = 1);
  // Clears the bar (or prints the last plain line) and hands the display on; idempotent. Call it
  // from the thread that created the Progress, once no other thread advances it.
  void finish();

 private:
  friend void printProgressMessage(const std::string& line);
  void report(std::int64_t nanoseconds);  // with the display lock held
  void draw(std::int64_t nanoseconds);    // with the display lock held
  std::int64_t elapsedNanoseconds() const;

  const std::string label_, unit_;
  const std::uint64_t total_, unitSize_;
  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool shown_ = false;  // owns the display; fixed by the constructor
  bool terminal_ = false;
  int columns_ = 80;
  std::atomic<std::uint64_t> done_{0};
  std::atomic<std::int64_t> due_{0};  // nanoseconds after start_ when the next report is due
  // Guarded by the display lock:
  bool drawn_ = false;    // a bar is on the terminal's current line
  bool printed_ = false;  // a plain line was printed
  bool finished_ = false;
};

// Writes `line` and a newline on stderr without tearing a bar drawn there: the bar is cleared, the
// line written, the bar drawn again. Messages of work that runs under a Progress go through it.
void printProgressMessage(const std::string& line);

// The pure formatting, for tests. `width` is the terminal's width: the line fits in width - 1
// columns (the bar takes 10 to 30, the label is shortened from the left if it must).
std::string progressBarLine(const std::string& label, std::uint64_t done, std::uint64_t total, const std::string& unit,
                            double seconds, int width, std::uint64_t unitSize = 1);
std::string progressPlainLine(const std::string& label, std::uint64_t done, std::uint64_t total,
                              const std::string& unit, double seconds, std::uint64_t unitSize = 1);

}  // namespace uvtk
