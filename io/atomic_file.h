// Output files appear whole or not at all: write to a temporary file in the target's folder,
// then rename it over the target.
#pragma once

#include <fstream>
#include <string>

namespace uvtk::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);  // throws OutputError if the temporary cannot be created
  ~AtomicFile();                          // removes the temporary unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return stream_; }
  void commit();  // flushes, checks the stream, renames; throws OutputError on any failure

 private:
  std::string path_;
  std::string temporaryPath_;
  std::ofstream stream_;
  bool committed_ = false;
};

// Writes `text` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace uvtk::io
