// Output files appear whole or not at all: written through a stream to a TemporaryFile beside the
// target, which commit() renames onto it.
#pragma once

#include <fstream>
#include <string>

#include "io/temporary_file.h"

namespace uvtk::io {

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);  // throws OutputError if the temporary cannot be created
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  void commit();  // flushes, checks the stream, renames; throws OutputError on any failure

 private:
  TemporaryFile temporary_;  // declared first: the stream closes before the temporary is removed
  std::ofstream stream_;
};

// Writes `text` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace uvtk::io
