#include "io/atomic_file.h"

#include <cerrno>

#include "core/error.h"

namespace uvtk::io {
namespace {

// Throws OutputError when `stream` could not open `file`'s path.
void checkOpened(const FileStream& stream, const TemporaryFile& file) {
  if (stream) return;
  throw writeError(file.shownName(),
                   file.writesStraight() ? "cannot open it" : "cannot open the temporary file " + file.path(),
                   stream.error());
}

// A temporary is new and empty: opened without O_TRUNC, which on ext4 marks the file for a flush
// of all its pages when closed (auto_da_alloc, meant for files truncated and rewritten in place):
// 0.17 s of the 366 MB map's wall, on the writing thread (docs/benchmarks.md). A device or FIFO
// written straight is opened with O_TRUNC, as a shell's `>` opens it.
bool truncates(const TemporaryFile& file) { return file.writesStraight(); }

// Flushes and closes `stream`; throws OutputError when any of its writes failed. A full disk
// (ENOSPC) or a file-size limit (EFBIG) shows as a failed write.
void closeChecked(FileStream& stream, const TemporaryFile& file) {
  const bool written = !stream.fail();
  if (!stream.close() || !written)
    throw writeError(file.shownName(), file.writesStraight() ? "writing failed" : "writing the temporary file failed",
                     stream.error());
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path)
    : temporary_(path), stream_(temporary_.path(), truncates(temporary_)) {
  checkOpened(stream_, temporary_);
}

void AtomicFile::commit() {
  closeChecked(stream_, temporary_);
  temporary_.commit();
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
  file.commit();
}

TemporaryFile& OutputSet::stage(const std::string& target) {
  auto file = std::make_unique<TemporaryFile>(target);
  std::lock_guard<std::mutex> lock(mutex_);
  files_.push_back(std::move(file));
  return *files_.back();
}

void OutputSet::write(const std::string& target, const std::function<void(std::ostream&)>& contents) {
  TemporaryFile& file = stage(target);
  FileStream stream(file.path(), truncates(file));
  checkOpened(stream, file);
  contents(stream);
  closeChecked(stream, file);
}

void OutputSet::writeText(const std::string& target, std::string_view text) {
  write(target, [text](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
}

void OutputSet::adopt(OutputSet& other) {
  std::scoped_lock lock(mutex_, other.mutex_);
  for (auto& file : other.files_) files_.push_back(std::move(file));
  other.files_.clear();
}

void OutputSet::publish() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<TemporaryFile*> files;
  for (const auto& file : files_) files.push_back(file.get());
  publishTogether(files);
  files_.clear();
}

}  // namespace uvtk::io
