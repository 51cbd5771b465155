#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/error.h"

namespace uvtk::io {

namespace {

std::string failure(const std::string& path, const std::string& what, int error) {
  return path + ": error: cannot write: " + what + ": " + std::strerror(error);
}

// The mode a newly created file gets (0666 less the umask); mkstemp itself creates 0600.
mode_t newFileMode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  std::vector<char> name(path_.begin(), path_.end());
  const std::string suffix = ".tmp.XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw OutputError(failure(path_, "cannot create a temporary file beside it", errno));
  ::fchmod(fd, newFileMode());
  ::close(fd);
  temporaryPath_ = name.data();
  stream_.open(temporaryPath_, std::ios::binary | std::ios::trunc);
  if (!stream_) {
    std::remove(temporaryPath_.c_str());
    throw OutputError(failure(path_, "cannot open the temporary file " + temporaryPath_, errno));
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    stream_.close();
    std::remove(temporaryPath_.c_str());
  }
}

void AtomicFile::commit() {
  stream_.flush();
  const bool written = static_cast<bool>(stream_);
  stream_.close();
  if (!written || stream_.fail()) throw OutputError(failure(path_, "writing the temporary file failed", errno));
  if (std::rename(temporaryPath_.c_str(), path_.c_str()) != 0)
    throw OutputError(failure(path_, "cannot rename the temporary file onto it", errno));
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
  file.commit();
}

}  // namespace uvtk::io
