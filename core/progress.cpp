// Progress on stderr. One lock guards the display (which Progress owns it, whether a bar is on the
// current line); advance() takes it only when a report is due and never waits for it.
#include "core/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>

namespace uvtk {

namespace {

constexpr std::int64_t kTerminalInterval = 100'000'000;  // ns: a bar redrawn 10 times a second, the first after 0.1 s
constexpr std::int64_t kPlainInterval = 5'000'000'000;   // ns: a log line every 5 s, the first after 5 s
constexpr int kMinBar = 10, kMaxBar = 30;

std::atomic<bool> gEnabled{false};
std::atomic<bool> gQuiet{false};
std::mutex gDisplay;
Progress* gOwner = nullptr;  // the Progress shown; guarded by gDisplay

// "1234/5000", or "12.3/50.0" when a displayed unit is unitSize counts.
std::string countsText(std::uint64_t done, std::uint64_t total, std::uint64_t unitSize) {
  char text[64];
  if (unitSize <= 1)
    std::snprintf(text, sizeof text, "%llu/%llu", static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total));
  else
    std::snprintf(text, sizeof text, "%.1f/%.1f", double(done) / double(unitSize), double(total) / double(unitSize));
  return text;
}

std::string secondsText(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

// One write per message, so that lines of several threads never interleave within a line.
void writeStderr(const std::string& text) { std::fwrite(text.data(), 1, text.size(), stderr); }

int terminalColumns() {
  winsize size{};
  return ::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 ? int(size.ws_col) : 80;
}

}  // namespace

void setProgressEnabled(bool enabled) { gEnabled = enabled; }
bool progressEnabled() { return gEnabled; }
void setQuiet(bool quiet) { gQuiet = quiet; }
bool quiet() { return gQuiet; }

std::string progressBarLine(const std::string& label, std::uint64_t done, std::uint64_t total, const std::string& unit,
                            double seconds, int width, std::uint64_t unitSize) {
  const std::string tail = " " + countsText(done, total, unitSize) + " " + unit + "  " + secondsText(seconds);
  // A line as wide as the terminal wraps, and "\r" then redraws only its second half.
  const int room = std::max(width, 1) - 1;
  const int fixed = int(tail.size()) + 3;  // " [" and "]"
  const int cells = std::clamp(room - int(label.size()) - fixed, kMinBar, kMaxBar);
  std::string shownLabel = label;
  const int labelRoom = room - fixed - cells;
  if (int(label.size()) > labelRoom)  // keep the end of the label: the file name of a path
    shownLabel = labelRoom > 3 ? "..." + label.substr(label.size() - std::size_t(labelRoom - 3)) : "";
  const std::uint64_t filled = total == 0 ? std::uint64_t(cells) : std::min(done, total) * std::uint64_t(cells) / total;
  std::string line =
      shownLabel + " [" + std::string(filled, '#') + std::string(std::size_t(cells) - filled, '.') + "]" + tail;
  if (int(line.size()) > room) line.resize(std::size_t(room));
  return line;
}

std::string progressPlainLine(const std::string& label, std::uint64_t done, std::uint64_t total,
                              const std::string& unit, double seconds, std::uint64_t unitSize) {
  return label + ": " + countsText(done, total, unitSize) + " " + unit + ", " + secondsText(seconds);
}

Progress::Progress(std::string label, std::uint64_t total, std::string unit, std::uint64_t unitSize)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total), unitSize_(unitSize) {
  if (!progressEnabled()) return;
  const std::lock_guard<std::mutex> lock(gDisplay);
  if (gOwner) return;
  gOwner = this;
  shown_ = true;
  terminal_ = ::isatty(STDERR_FILENO) != 0;
  if (terminal_) columns_ = terminalColumns();
  // Work too short to notice draws nothing: no flicker, and no writes inside the timed loops of `uvtk bench`.
  due_ = terminal_ ? kTerminalInterval : kPlainInterval;
}

Progress::~Progress() { finish(); }

std::int64_t Progress::elapsedNanoseconds() const {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::advance(std::uint64_t count) {
  if (!shown_) return;
  done_.fetch_add(count, std::memory_order_relaxed);
  const std::int64_t now = elapsedNanoseconds();
  if (now < due_.load(std::memory_order_relaxed)) return;
  // Another thread reporting right now makes this report unnecessary: never wait.
  std::unique_lock<std::mutex> lock(gDisplay, std::try_to_lock);
  if (lock.owns_lock() && !finished_) report(now);
}

void Progress::report(std::int64_t nanoseconds) {
  if (nanoseconds < due_.load(std::memory_order_relaxed)) return;  // another thread just reported
  due_ = nanoseconds + (terminal_ ? kTerminalInterval : kPlainInterval);
  draw(nanoseconds);
}

void Progress::draw(std::int64_t nanoseconds) {
  const double seconds = double(nanoseconds) * 1e-9;
  const std::uint64_t done = done_.load(std::memory_order_relaxed);
  if (terminal_) {
    // Written over the old bar, then the rest of the line cleared: no flicker.
    writeStderr("\r" + progressBarLine(label_, done, total_, unit_, seconds, columns_, unitSize_) + "\033[K");
    drawn_ = true;
  } else {
    writeStderr(progressPlainLine(label_, done, total_, unit_, seconds, unitSize_) + "\n");
    printed_ = true;
  }
}

void Progress::finish() {
  if (!shown_) return;
  const std::lock_guard<std::mutex> lock(gDisplay);
  if (finished_) return;
  finished_ = true;
  if (drawn_) writeStderr("\r\033[K");
  // A log that showed the work under way also shows where it ended.
  if (printed_) draw(elapsedNanoseconds());
  gOwner = nullptr;
}

void printProgressMessage(const std::string& line) {
  const std::lock_guard<std::mutex> lock(gDisplay);
  const bool bar = gOwner && gOwner->drawn_;
  writeStderr((bar ? "\r\033[K" : "") + line + "\n");
  if (bar) gOwner->draw(gOwner->elapsedNanoseconds());
}

}  // namespace uvtk
