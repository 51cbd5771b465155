// The stream the outputs' temporaries are written through (io/atomic_file.h): a file opened by
// path, written in blocks, whose write-back to the disk starts as it is written. A large output
// left dirty in the page cache until it is renamed over its target made the rename wait while
// ext4 flushed all of it (auto_da_alloc, ext4's safety for files replaced by rename): 0.16 to 0.23
// s of the 366 MB map, with both cores idle (docs/benchmarks.md). Started a few megabytes at a
// time (sync_file_range), and for the rest when the file is closed, by the thread that writes it,
// the disk writes while the program still computes (a small map writes its file beside its
// judgement).
#pragma once

#include <sys/types.h>

#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace uvtk::io {

class FileStream : public std::ostream {
 public:
  // Opens `path` for writing (created if absent; emptied first when `truncate`). When it cannot be
  // opened the stream is bad and error() holds the reason.
  FileStream(const std::string& path, bool truncate);
  ~FileStream() override;
  FileStream(const FileStream&) = delete;
  FileStream& operator=(const FileStream&) = delete;

  // Writes what is buffered and closes the file: false when a write or the close failed.
  bool close();
  // errno of the first failure (opening, a write, the close); 0 when there was none.
  int error() const { return buffer_.error(); }

 private:
  class Buffer : public std::streambuf {
   public:
    bool open(const std::string& path, bool truncate);
    bool close();
    int error() const { return error_; }
    ~Buffer() override;

   protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* data, std::streamsize count) override;
    int sync() override;

   private:
    bool flushBuffer();
    bool writeAll(const char* data, std::size_t count);
    void startWriteback();
    int fd_ = -1;
    int error_ = 0;
    std::unique_ptr<char[]> storage_;  // not value-initialised: a small file touches one page of it
    off_t written_ = 0;          // bytes the file has received
    off_t writebackStarted_ = 0;  // bytes before which write-back has been started
  };
  Buffer buffer_;
};

}  // namespace uvtk::io
