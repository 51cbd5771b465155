#include "io/temporary_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <vector>

#include "core/error.h"

namespace uvtk::io {
namespace {

namespace fs = std::filesystem;

// The named temporaries and backups that exist, for the signal handler, which may only call
// async-signal-safe functions: a fixed table of fixed-size paths. A slot is published before the
// name exists (mkstemps writes the name in place; linkat and link come after), so a signal that
// arrives once the file exists always finds it. More simultaneous names than slots (or longer
// paths) still work, but are not removed on a signal.
constexpr int kSlots = 256;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 published
  char path[kMaxPath] = {};  // initialised, so the table is constant-initialised: no page touched at start
};
std::array<Slot, kSlots> gSlots;

// Publishing in progress (publishTogether) and a signal that arrived meanwhile: the handler defers
// it until the renames are done, whichever thread it lands on.
std::atomic<int> gPublishing{0};
std::atomic<int> gDeferredSignal{0};

std::atomic<bool> gStdoutIsAnOutput{false};
std::atomic<bool> gDivertStdout{false};
int gStdoutFd = STDOUT_FILENO;  // where staged "-" outputs go: fd 1, or its copy once diverted

// Once an output is "-", what else the program prints to stdout goes to stderr (see
// divertStdoutForOutputs); the output itself goes to the original stdout, kept as gStdoutFd.
void claimStdout() {
  if (gStdoutIsAnOutput.exchange(true) || !gDivertStdout.load()) return;
  std::fflush(stdout);
  const int kept = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (kept < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return;
  gStdoutFd = kept;
}

// A published slot holding `name`, or -1 when none is free or the name is too long.
int publish(const std::string& name) {
  if (name.size() >= kMaxPath) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!gSlots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(gSlots[i].path, name.c_str(), name.size() + 1);
    gSlots[i].state.store(2);
    return i;
  }
  return -1;
}

void unregister(int slot) {
  if (slot >= 0) gSlots[slot].state.store(0);
}

void removeTemporariesAndDie(int signal) {
  for (Slot& slot : gSlots)
    if (slot.state.load() == 2) ::unlink(slot.path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

extern "C" void onTerminatingSignal(int signal) {
  if (gPublishing.load() > 0) {
    gDeferredSignal.store(signal);
    return;
  }
  removeTemporariesAndDie(signal);
}

// Holds terminating signals back while it lives, then handles the one that arrived, if any.
class HeldSignals {
 public:
  HeldSignals() { ++gPublishing; }
  ~HeldSignals() { release(); }
  HeldSignals(const HeldSignals&) = delete;
  HeldSignals& operator=(const HeldSignals&) = delete;
  void release() {
    if (released_) return;
    released_ = true;
    if (--gPublishing == 0)
      if (const int signal = gDeferredSignal.exchange(0)) removeTemporariesAndDie(signal);
  }

 private:
  bool released_ = false;
};

// The mode a newly created file gets (0666 less the umask). Read once, before this process creates
// any file through this module: umask can only be read by setting it, and a file created by another
// thread in between would get the wrong mode.
mode_t newFileMode() {
  static const mode_t mode = [] {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
  }();
  return mode;
}

// Six random letters and digits for a hidden name; uniqueness comes from O_EXCL or EEXIST, not from these.
std::string randomLetters() {
  static const char kLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  // Seeded by getrandom(2), not std::random_device, whose construction probes the processor for
  // RDRAND: CPUID, about 6 us a call on a virtual machine, 0.04 ms of every process that writes.
  thread_local std::mt19937_64 random([] {
    std::uint64_t seed = 0;
    if (::getrandom(&seed, sizeof seed, GRND_NONBLOCK) != ssize_t(sizeof seed))
      seed = std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
    return seed ^ (std::uint64_t(::getpid()) << 32);
  }());
  std::string letters(6, ' ');
  for (char& c : letters) c = kLetters[random() % (sizeof kLetters - 1)];
  return letters;
}

// `target` with its symbolic links followed, through chains; a dangling link gives the name it leads to.
std::string followLinks(const std::string& target) {
  std::string path = target;
  for (int hops = 0; hops < 40; ++hops) {  // Linux's own limit
    struct stat status {};
    if (::lstat(path.c_str(), &status) != 0 || !S_ISLNK(status.st_mode)) return path;
    std::vector<char> buffer(PATH_MAX);
    const ssize_t length = ::readlink(path.c_str(), buffer.data(), buffer.size());
    if (length < 0) throw writeError(target, "cannot read the link " + path, errno);
    const fs::path link(std::string(buffer.data(), std::size_t(length)));
    path = link.is_absolute() ? link.string() : (fs::path(path).parent_path() / link).string();
  }
  throw writeError(target, "cannot follow its links", ELOOP);
}

// Links `from` (a name, or "/proc/self/fd/N") to an unused name "PREFIX" + 6 letters + `suffix`,
// published in the signal table first; returns the name and sets `slot`, or "" with errno set.
std::string linkToUnusedName(const std::string& from, const std::string& prefix, const std::string& suffix, int& slot) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = prefix + randomLetters() + suffix;
    slot = publish(name);
    if (::linkat(AT_FDCWD, from.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return name;
    const int error = errno;
    unregister(slot);
    slot = -1;
    errno = error;
    if (error != EEXIST) return "";
  }
  return "";
}

// The start of a hidden name beside `place`: "FOLDER/.NAME" + tag, NAME cut so that the whole name,
// with six random letters and `suffix` after it, fits in a folder entry (NAME_MAX bytes): any name
// the user may give has a temporary. A suffix too long to leave room is left out (`suffix` becomes "").
std::string hiddenPrefix(const std::string& place, const std::string& tag, std::string& suffix) {
  const fs::path p(place);
  const std::string name = p.filename().string();
  constexpr std::size_t kRandomLetters = 6, kShortestName = 8;
  if (1 + kShortestName + tag.size() + kRandomLetters + suffix.size() > NAME_MAX) suffix.clear();
  const std::size_t room = NAME_MAX - 1 - tag.size() - kRandomLetters - suffix.size();
  return (p.parent_path() / ("." + name.substr(0, room) + tag)).string();
}

}  // namespace

OutputError writeError(const std::string& target, const std::string& what, int error) {
  return OutputError(target + ": error: cannot write: " + what +
                     (error ? std::string(": ") + std::strerror(error) : ""));
}

TemporaryFile::TemporaryFile(const std::string& target) : target_(target) {
  std::string folder;
  if (target == "-") {
    kind_ = Kind::Stdout;
    claimStdout();
    const char* tmp = std::getenv("TMPDIR");
    folder = tmp && *tmp ? tmp : "/tmp";
    createUnnamed(folder);
    if (fd_ < 0) createNamed(folder, "uvtk-stdout");
    return;
  }
  place_ = followLinks(target);
  struct stat status {};
  if (::stat(place_.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) throw writeError(target, "it is a folder");
    if (!S_ISREG(status.st_mode)) {  // a device, a FIFO, a socket: never replaced
      kind_ = Kind::Direct;
      path_ = place_;
      return;
    }
  }
  folder = fs::path(place_).parent_path().string();
  createUnnamed(folder.empty() ? "." : folder);
  if (fd_ < 0) createNamed(folder, fs::path(place_).filename().string());
}

void TemporaryFile::createUnnamed(const std::string& folder) {
#ifdef O_TMPFILE
  const int fd = ::open(folder.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, newFileMode());
  if (fd < 0) {
    // No O_TMPFILE in this file system (EOPNOTSUPP) or kernel (EISDIR, EINVAL): the named temporary.
    if (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL) return;
    throw writeError(shownName(), "cannot create a temporary file beside it", errno);
  }
  const std::string proc = "/proc/self/fd/" + std::to_string(fd);
  if (::access(proc.c_str(), W_OK) != 0) {  // no /proc: writers could not open it
    ::close(fd);
    return;
  }
  fd_ = fd;
  path_ = proc;
#else
  (void)folder;
#endif
}

void TemporaryFile::createNamed(const std::string& folder, const std::string& name) {
  std::string extension = fs::path(name).extension().string();
  const std::string pattern = hiddenPrefix((fs::path(folder) / name).string(), ".tmp.", extension) + "XXXXXX" + extension;
  const mode_t mode = newFileMode();
  slot_ = publish(pattern);
  std::vector<char> unpublished;
  if (slot_ < 0) unpublished.assign(pattern.c_str(), pattern.c_str() + pattern.size() + 1);
  char* buffer = slot_ >= 0 ? gSlots[slot_].path : unpublished.data();
  const int fd = ::mkstemps(buffer, static_cast<int>(extension.size()));
  if (fd < 0) {
    const int error = errno;
    unregister(slot_);
    slot_ = -1;
    throw writeError(shownName(), "cannot create a temporary file beside it", error);
  }
  named_ = path_ = buffer;
  ::fchmod(fd, mode);  // mkstemps creates 0600
  ::close(fd);
}

void TemporaryFile::giveHiddenName() {
  std::string extension = fs::path(place_).extension().string();
  const std::string prefix = hiddenPrefix(place_, ".tmp.", extension);
  named_ = linkToUnusedName(path_, prefix, extension, slot_);
  if (named_.empty()) throw writeError(shownName(), "cannot link the temporary file into its folder", errno);
  ::close(fd_);
  fd_ = -1;
  path_ = named_;
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!named_.empty() && (!published_ || kind_ == Kind::Stdout)) ::unlink(named_.c_str());
  unregister(slot_);
}

const std::string& TemporaryFile::shownName() const {
  static const std::string kStdout = "<stdout>";
  return kind_ == Kind::Stdout ? kStdout : target_;
}

void TemporaryFile::commit() { publishTogether({this}); }

namespace {

// Copies the staged content of standard output (an open file or a name) to fd 1.
void copyToStdout(int fd, const std::string& named, const std::string& shown) {
  const int source = fd >= 0 ? fd : ::open(named.c_str(), O_RDONLY | O_CLOEXEC);
  if (source < 0) throw writeError(shown, "cannot reopen the temporary file", errno);
  std::vector<char> buffer(1 << 16);
  off_t offset = 0;
  int error = 0;
  const char* what = "";
  for (;;) {
    const ssize_t got = ::pread(source, buffer.data(), buffer.size(), offset);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      if (got < 0) error = errno, what = "reading the temporary file failed";
      break;
    }
    offset += got;
    for (ssize_t sent = 0; sent < got && !error;) {
      const ssize_t n = ::write(gStdoutFd, buffer.data() + sent, std::size_t(got - sent));
      if (n < 0 && errno != EINTR) error = errno, what = "writing to standard output failed";
      if (n > 0) sent += n;
    }
    if (error) break;
  }
  if (fd < 0) ::close(source);
  if (error) throw writeError(shown, what, error);
}

}  // namespace

void publishTogether(const std::vector<TemporaryFile*>& files) {
  struct Step {
    TemporaryFile* file;
    std::string backup;  // a hard link to the target's previous version, while publishing
    int backupSlot = -1;
    bool movedAside = false;  // the backup is the previous version's only name
    bool replaced = false;
  };
  std::vector<Step> steps;
  std::size_t toStdout = 0;
  for (TemporaryFile* file : files) {
    UVTK_CHECK(!file->published_);
    if (file->kind_ == TemporaryFile::Kind::Replace) steps.push_back({file, "", -1, false, false});
    toStdout += file->kind_ == TemporaryFile::Kind::Stdout;
  }
  // A lone output needs no backup: its rename is the whole step.
  const bool backups = steps.size() + toStdout > 1;
  const auto undo = [&steps] {
    for (auto s = steps.rbegin(); s != steps.rend(); ++s) {
      if (s->replaced && s->backup.empty()) ::unlink(s->file->place_.c_str());
      const bool restore = !s->backup.empty() && (s->replaced || s->movedAside);
      if (restore && ::rename(s->backup.c_str(), s->file->place_.c_str()) == 0) s->backup.clear();
      if (!s->backup.empty()) ::unlink(s->backup.c_str());
      unregister(s->backupSlot);
    }
  };

  HeldSignals held;
  try {
    for (Step& s : steps)
      if (s.file->fd_ >= 0) s.file->giveHiddenName();
    for (Step& s : steps) {
      struct stat status {};
      // Only a regular file has a previous version to keep; anything else (a folder made there
      // since) makes the rename fail.
      if (!backups || ::lstat(s.file->place_.c_str(), &status) != 0 || !S_ISREG(status.st_mode)) continue;
      std::string noSuffix;
      const std::string prefix = hiddenPrefix(s.file->place_, ".bak.", noSuffix);
      s.backup = linkToUnusedName(s.file->place_, prefix, "", s.backupSlot);
      if (!s.backup.empty()) continue;
      // A file system without hard links (FAT): the previous version moves aside instead, so the
      // target is absent until its new version arrives.
      const int error = errno;
      s.backup = prefix + randomLetters();
      s.backupSlot = publish(s.backup);
      if (::rename(s.file->place_.c_str(), s.backup.c_str()) != 0) {
        s.backup.clear();
        throw writeError(s.file->shownName(), "cannot keep its previous version", error);
      }
      s.movedAside = true;
    }
    for (Step& s : steps) {
      if (::rename(s.file->named_.c_str(), s.file->place_.c_str()) != 0)
        throw writeError(s.file->shownName(), "cannot rename the temporary file onto it", errno);
      s.replaced = true;
      s.file->named_.clear();
      unregister(s.file->slot_);
      s.file->slot_ = -1;
    }
  } catch (...) {
    undo();
    throw;  // `held` handles a signal that arrived
  }
  held.release();
  try {
    for (TemporaryFile* file : files)
      if (file->kind_ == TemporaryFile::Kind::Stdout) copyToStdout(file->fd_, file->named_, file->shownName());
  } catch (...) {
    undo();
    throw;
  }
  for (Step& s : steps) {
    if (!s.backup.empty()) ::unlink(s.backup.c_str());
    unregister(s.backupSlot);
  }
  for (TemporaryFile* file : files) file->published_ = true;
}

bool stdoutIsAnOutput() { return gStdoutIsAnOutput.load(); }

void divertStdoutForOutputs() { gDivertStdout = true; }

void installInterruptHandlers() {
  std::vector<int> signals = {SIGINT,  SIGTERM, SIGHUP,    SIGQUIT, SIGPIPE, SIGUSR1,
                              SIGUSR2, SIGALRM, SIGXCPU,   SIGVTALRM, SIGPROF, SIGPOLL};
#ifdef SIGSTKFLT
  signals.push_back(SIGSTKFLT);
#endif
#ifdef SIGPWR
  signals.push_back(SIGPWR);
#endif
  for (int signal = SIGRTMIN; signal <= SIGRTMAX; ++signal) signals.push_back(signal);

  struct sigaction action {};
  action.sa_handler = onTerminatingSignal;
  action.sa_flags = SA_RESTART;  // a deferred signal returns to the interrupted call
  sigemptyset(&action.sa_mask);
  for (const int signal : signals) sigaddset(&action.sa_mask, signal);
  for (const int signal : signals) {
    struct sigaction previous {};
    // A signal ignored by whoever started us (nohup, a shell's background job) stays ignored, and
    // a handler someone else installed stays.
    if (::sigaction(signal, nullptr, &previous) != 0) continue;
    if (previous.sa_handler != SIG_DFL && previous.sa_handler != onTerminatingSignal) continue;
    ::sigaction(signal, &action, nullptr);
  }
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace uvtk::io
