// The temporary that every output is written to before it is renamed onto its target, so that an
// output appears whole or not at all: after an error, an interrupt (SIGINT, SIGTERM, SIGHUP) or a
// full disk, the target is either absent or exactly as it was.
#pragma once

#include <string>

#include "core/error.h"

namespace uvtk::io {

// The one form of every output failure: "TARGET: error: cannot write: WHAT[: the reason errno gives]".
OutputError writeError(const std::string& target, const std::string& what, int error = 0);

class TemporaryFile {
 public:
  // Creates ".NAME.tmp.XXXXXX.EXT" beside `target` (hidden from globs, the extension kept last for
  // writers that look at it) with the mode a new file gets. Throws OutputError when it cannot.
  explicit TemporaryFile(const std::string& target);
  ~TemporaryFile();  // removes the temporary unless commit() succeeded
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& target() const { return target_; }

  // Renames the temporary onto the target; throws OutputError (and removes it) on failure.
  void commit();

 private:
  std::string target_, path_;
  int slot_ = -1;  // its entry in the table the signal handler empties, or -1 if the table was full
  bool committed_ = false;
};

// Installs the handlers that make interrupts lose nothing: SIGINT, SIGTERM and SIGHUP remove every
// temporary that exists, then end the process by the same signal (exit status 128 + signal); SIGXFSZ
// is ignored, so that exceeding a file-size limit is a write error (EFBIG) like a full disk. The
// command line calls it once at start; a library user may or may not.
void installInterruptHandlers();

}  // namespace uvtk::io
