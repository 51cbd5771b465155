// Where an output is written before it is published, so that it appears whole or not at all: after
// an error, a caught signal or a full disk, a target is either absent or exactly as it was.
#pragma once

#include <string>
#include <vector>

#include "core/error.h"

namespace uvtk::io {

// The one form of every output failure: "TARGET: error: cannot write: WHAT[: the reason errno gives]".
OutputError writeError(const std::string& target, const std::string& what, int error = 0);

// The staged content of one output, by what its path names:
// - a regular file or a new name: a temporary in the target's folder, renamed onto it when published.
//   On Linux an unnamed one (O_TMPFILE, written through "/proc/self/fd/N"), which no way of ending
//   the process can leave behind; it gets a hidden name (".NAME.tmp.XXXXXX.EXT") only when it is
//   published. Where the file system or /proc does not allow that, the named temporary from the start.
// - a symbolic link: the same for the file it leads to (links followed once, through chains; a
//   dangling link's target is created), so the link stays a link.
// - a character or block device, a FIFO or a socket: the target itself, written straight; it is
//   never replaced or removed, and what was written to it cannot be taken back.
// - "-": standard output. The content is staged in an unnamed temporary file and copied to fd 1
//   when published, so that nothing half-written reaches it.
class TemporaryFile {
 public:
  // Throws OutputError when the temporary cannot be created (missing folder, no permission, the
  // target is a folder).
  explicit TemporaryFile(const std::string& target);
  ~TemporaryFile();  // discards the content unless it was published
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  // The path writers open (std::ofstream, OpenImageIO): "/proc/self/fd/N", a hidden temporary, or
  // the device itself.
  const std::string& path() const { return path_; }
  const std::string& target() const { return target_; }  // as given
  const std::string& shownName() const;                  // in messages: the target, "<stdout>" for "-"
  bool writesStraight() const { return kind_ == Kind::Direct; }

  // Publishes this output alone: publishTogether({this}).
  void commit();

 private:
  friend void publishTogether(const std::vector<TemporaryFile*>& files);
  enum class Kind { Replace, Direct, Stdout };

  void createUnnamed(const std::string& folder);
  void createNamed(const std::string& folder, const std::string& name);
  void giveHiddenName();  // links an unnamed temporary into place_'s folder (Replace only)

  Kind kind_ = Kind::Replace;
  std::string target_;
  std::string place_;  // the file replaced: the target with its links followed (Replace only)
  std::string path_;
  std::string named_;  // the temporary's name in the folder, once it has one
  int fd_ = -1;        // the unnamed temporary, open until it is published
  int slot_ = -1;      // named_'s entry in the table the signal handler empties, or -1
  bool published_ = false;
};

// Puts every file in place in one step (the outputs of one command, OutputSet): each temporary
// gets its hidden name first, then each existing target a hard-link backup, then every temporary is
// renamed onto its target, then standard output gets its copy. When a step fails, the targets
// already replaced are renamed back from their backups, new names are removed, and OutputError is
// thrown: none of the new outputs appears and the previous versions stay. A signal that arrives
// meanwhile is handled when the renames are done, so it cannot split them.
//
// What remains: the renames are separate system calls, so a crash of the machine or SIGKILL among
// them (a few microseconds per output) can leave some targets new and some old, and the hidden
// names and backups behind; nothing makes several renames one in POSIX. An interrupt while the copy
// to standard output runs (which can block on a slow reader, so signals are not held back then)
// leaves the files published and standard output cut short. Straight-written devices and FIFOs
// received their bytes while they were written.
void publishTogether(const std::vector<TemporaryFile*>& files);

// True once an output named "-" was created in this process: the command's summary should then go
// to stderr so that it does not mix with the output on stdout.
bool stdoutIsAnOutput();

// Makes stdout belong to the outputs named "-": once the first is created, everything else the
// program prints on stdout (summaries, tables) goes to stderr instead. The command line calls it
// once at start; a library user who prints its own text on stdout should not.
void divertStdoutForOutputs();

// Installs the handlers that make interrupts lose nothing: every catchable signal whose default
// action ends the process (SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGUSR2, SIGALRM,
// SIGXCPU, SIGVTALRM, SIGPROF, SIGPOLL, SIGSTKFLT, SIGPWR and the real-time signals; not the fault
// signals SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP and SIGSYS, which the sanitizers own)
// removes every named temporary, then ends the process by the same signal (exit status 128 +
// signal). A signal ignored by whoever started us (nohup) stays ignored, and one with a handler of
// its own keeps it. SIGXFSZ is ignored, so that exceeding a file-size limit is a write error (EFBIG)
// like a full disk. The command line calls it once at start; a library user may or may not.
void installInterruptHandlers();

}  // namespace uvtk::io
