#include "io/temporary_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/error.h"

namespace uvtk::io {
namespace {

// The temporaries that exist, for the signal handler, which may only call async-signal-safe
// functions: a fixed table of fixed-size paths. A slot is published before the file exists and
// mkstemps writes the name in place, so a signal that arrives once the file exists always finds
// it. More simultaneous temporaries than slots (or longer paths) still work, but are not removed
// on a signal.
constexpr int kSlots = 256;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 published
  char path[kMaxPath];
};
std::array<Slot, kSlots> gSlots;

// A published slot holding `pattern`, or -1 when none is free or the pattern is too long.
int publish(const std::string& pattern) {
  if (pattern.size() >= kMaxPath) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!gSlots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(gSlots[i].path, pattern.c_str(), pattern.size() + 1);
    gSlots[i].state.store(2);
    return i;
  }
  return -1;
}

void unregister(int slot) {
  if (slot >= 0) gSlots[slot].state.store(0);
}

extern "C" void removeTemporariesAndDie(int signal) {
  for (Slot& slot : gSlots)
    if (slot.state.load() == 2) ::unlink(slot.path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// The mode a newly created file gets (0666 less the umask); mkstemps itself creates 0600.
mode_t newFileMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

OutputError writeError(const std::string& target, const std::string& what, int error) {
  return OutputError(target + ": error: cannot write: " + what +
                     (error ? std::string(": ") + std::strerror(error) : ""));
}

TemporaryFile::TemporaryFile(const std::string& target) : target_(target) {
  const std::filesystem::path t(target);
  const std::string extension = t.extension().string();
  const std::string name = (t.parent_path() / ("." + t.filename().string() + ".tmp.XXXXXX" + extension)).string();
  slot_ = publish(name);
  std::vector<char> unpublished;
  if (slot_ < 0) unpublished.assign(name.c_str(), name.c_str() + name.size() + 1);
  char* buffer = slot_ >= 0 ? gSlots[slot_].path : unpublished.data();
  const int fd = ::mkstemps(buffer, static_cast<int>(extension.size()));
  if (fd < 0) {
    const int error = errno;
    unregister(slot_);
    throw writeError(target, "cannot create a temporary file beside it", error);
  }
  path_ = buffer;
  ::fchmod(fd, newFileMode());
  ::close(fd);
}

TemporaryFile::~TemporaryFile() {
  if (!committed_) ::unlink(path_.c_str());
  unregister(slot_);
}

void TemporaryFile::commit() {
  UVTK_CHECK(!committed_);
  if (std::rename(path_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    ::unlink(path_.c_str());
    throw writeError(target_, "cannot rename the temporary file onto it", error);
  }
  committed_ = true;
}

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = removeTemporariesAndDie;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction previous {};
    // A signal ignored by whoever started us (nohup, a shell's background job) stays ignored.
    if (::sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(signal, &action, nullptr);
  }
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace uvtk::io
