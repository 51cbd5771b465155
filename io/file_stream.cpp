#include "io/file_stream.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace uvtk::io {
namespace {

constexpr std::size_t kBufferBytes = std::size_t(1) << 16;
// Write-back is started for each whole step as it is written, and for the rest at the close.
constexpr off_t kWritebackStep = off_t(8) << 20;

}  // namespace

bool FileStream::Buffer::open(const std::string& path, bool truncate) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | (truncate ? O_TRUNC : 0), 0666);
  if (fd_ < 0) {
    error_ = errno;
    return false;
  }
  storage_.reset(new char[kBufferBytes]);
  setp(storage_.get(), storage_.get() + kBufferBytes);
  return true;
}

FileStream::Buffer::~Buffer() {
  if (fd_ >= 0) ::close(fd_);
}

bool FileStream::Buffer::writeAll(const char* data, std::size_t count) {
  if (error_ != 0 || fd_ < 0) return false;  // a failed file is written no more: its first error stays
  while (count > 0) {
    const ssize_t n = ::write(fd_, data, count);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = n < 0 ? errno : EIO;
      return false;
    }
    data += n, count -= std::size_t(n), written_ += n;
  }
  startWriteback();
  return true;
}

void FileStream::Buffer::startWriteback() {
  // Advice: a file that has none (a FIFO, a device) or a kernel without it writes as before.
  while (written_ - writebackStarted_ >= kWritebackStep) {
    if (::sync_file_range(fd_, writebackStarted_, kWritebackStep, SYNC_FILE_RANGE_WRITE) != 0) {
      writebackStarted_ = written_;
      return;
    }
    writebackStarted_ += kWritebackStep;
  }
}

bool FileStream::Buffer::flushBuffer() {
  const std::size_t pending = std::size_t(pptr() - pbase());
  if (storage_) setp(storage_.get(), storage_.get() + kBufferBytes);  // none: the file did not open
  return pending == 0 || writeAll(storage_.get(), pending);
}

FileStream::Buffer::int_type FileStream::Buffer::overflow(int_type c) {
  if (!flushBuffer()) return traits_type::eof();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  *pptr() = traits_type::to_char_type(c);
  pbump(1);
  return c;
}

std::streamsize FileStream::Buffer::xsputn(const char* data, std::streamsize count) {
  const std::size_t n = std::size_t(count);
  if (n <= std::size_t(epptr() - pptr())) {  // fits in the buffer
    std::memcpy(pptr(), data, n);
    pbump(int(n));
    return count;
  }
  // A block larger than the room left goes straight to the file after what is buffered.
  if (!flushBuffer() || !writeAll(data, n)) return 0;
  return count;
}

int FileStream::Buffer::sync() { return flushBuffer() ? 0 : -1; }

bool FileStream::Buffer::close() {
  if (fd_ < 0) return error_ == 0;
  const bool flushed = flushBuffer();
  // The rest's write-back started too, by the thread that wrote the file (a small map's writes
  // beside its judgement): the rename over an existing target then finds little left to flush.
  if (flushed && written_ > writebackStarted_) ::sync_file_range(fd_, writebackStarted_, 0, SYNC_FILE_RANGE_WRITE);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0 && error_ == 0) error_ = errno;
  return flushed && error_ == 0;
}

FileStream::FileStream(const std::string& path, bool truncate) : std::ostream(nullptr) {
  rdbuf(&buffer_);
  if (!buffer_.open(path, truncate)) setstate(std::ios::badbit);
}

FileStream::~FileStream() { buffer_.close(); }

bool FileStream::close() {
  const bool closed = buffer_.close();
  if (!closed) setstate(std::ios::badbit);
  return closed;
}

}  // namespace uvtk::io
