#include "io/ordered_text.h"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <ostream>

#include "core/parallel.h"

namespace uvtk::io {

void TextBlock::grow(std::size_t bytes) {
  capacity_ = std::max(bytes, 2 * capacity_);
  std::unique_ptr<char[]> larger(new char[capacity_]);  // not value-initialised: written before read
  if (size_ > 0) std::memcpy(larger.get(), data_.get(), size_);
  data_ = std::move(larger);
}

void OrderedText::text(std::string_view text) { out_.write(text.data(), static_cast<std::streamsize>(text.size())); }

void OrderedText::blocks(std::size_t count, const std::function<void(std::size_t, TextBlock&)>& format) {
  const int threads = std::min<std::size_t>(threadCount(threads_), std::max<std::size_t>(count, 1));
  const auto write = [&](const TextBlock& block) {
    out_.write(block.text().data(), static_cast<std::streamsize>(block.text().size()));
  };
  if (threads <= 1) {
    if (spare_.empty()) spare_.emplace_back();
    for (std::size_t i = 0; i < count; ++i) {
      spare_[0].clear();
      format(i, spare_[0]);
      write(spare_[0]);
    }
    return;
  }

  // Blocks formatted but not yet written wait in `done` (slot i % ahead); a thread waits before
  // formatting a block more than `ahead` past the next due, which bounds the memory held.
  const std::size_t ahead = 2 * static_cast<std::size_t>(threads);
  spare_.resize(std::max(spare_.size(), ahead));
  std::vector<char> done(ahead, 0);
  std::mutex mutex;
  std::condition_variable written;
  std::size_t due = 0;   // the next block to write
  bool writing = false;  // a thread is writing (the others leave their blocks to it)
  parallelFor(static_cast<int>(count), threads, [&](int index) {
    const std::size_t i = static_cast<std::size_t>(index);
    std::unique_lock<std::mutex> lock(mutex);
    written.wait(lock, [&] { return i < due + ahead; });
    TextBlock& block = spare_[i % ahead];
    lock.unlock();
    block.clear();
    format(i, block);
    lock.lock();
    done[i % ahead] = 1;
    if (writing) return;
    writing = true;
    while (due < count && done[due % ahead]) {
      TextBlock& next = spare_[due % ahead];
      lock.unlock();
      write(next);
      lock.lock();
      done[due % ahead] = 0;
      ++due;
      written.notify_all();
    }
    writing = false;
  });
}

}  // namespace uvtk::io
