#include "io/atomic_file.h"

#include <cerrno>

#include "core/error.h"

namespace uvtk::io {

AtomicFile::AtomicFile(const std::string& path) : temporary_(path) {
  errno = 0;
  stream_.open(temporary_.path(), std::ios::binary | std::ios::trunc);
  if (!stream_) throw writeError(path, "cannot open the temporary file " + temporary_.path(), errno);
}

void AtomicFile::commit() {
  // A full disk (ENOSPC) or a file-size limit (EFBIG) shows as a failed write. A failed stream writes
  // no more, so errno still holds the reason its write failed.
  if (stream_) stream_.flush();
  const bool written = static_cast<bool>(stream_);
  int error = errno;
  stream_.close();
  if (written) error = errno;
  if (!written || stream_.fail()) throw writeError(temporary_.target(), "writing the temporary file failed", error);
  temporary_.commit();
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
  file.commit();
}

}  // namespace uvtk::io
