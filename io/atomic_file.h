// Output files appear whole or not at all (io/temporary_file.h): one at a time (AtomicFile,
// writeFileAtomically), or the outputs of one command together (OutputSet), so that a failure of
// any of them leaves none.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "io/file_stream.h"
#include "io/temporary_file.h"

namespace uvtk::io {

class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);  // throws OutputError if the temporary cannot be created
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return stream_; }
  void commit();  // flushes, checks the stream, publishes; throws OutputError on any failure

 private:
  TemporaryFile temporary_;  // declared first: the stream closes before the temporary is removed
  FileStream stream_;
};

// Writes `text` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& text);

// The outputs of one command, staged one by one, each written completely, then published in one
// step (publishTogether): on any failure, before or during publish(), none of them appears and
// the previous versions stay. What is not published when the set ends is discarded.
class OutputSet {
 public:
  // Stages `target` for a writer that opens a path itself (images): it writes to the returned
  // file's path() before publish().
  TemporaryFile& stage(const std::string& target);
  // Stages `target` with what `contents` writes to the stream; throws OutputError when the
  // writing fails (full disk, file-size limit).
  void write(const std::string& target, const std::function<void(std::ostream&)>& contents);
  void writeText(const std::string& target, std::string_view text);

  // Moves the staged outputs of `other` into this set; both may be used by other threads meanwhile.
  void adopt(OutputSet& other);

  // Puts every staged output in place; throws OutputError (then none was). The set is empty after.
  void publish();

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<TemporaryFile>> files_;
};

}  // namespace uvtk::io
