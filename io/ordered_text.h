// Text made in blocks on several threads and written in order, so that a large text file's
// writer formats on every core while its output stays one stream, written about a block (a
// fraction of a megabyte) per call.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string_view>
#include <vector>

namespace uvtk::io {

// The text of one block: a buffer written through raw pointers, so that numbers are formatted
// (std::to_chars) straight into it.
class TextBlock {
 public:
  // At least `bytes` writable bytes after the text so far; write there, then commit().
  char* room(std::size_t bytes) {
    if (size_ + bytes > capacity_) grow(size_ + bytes);
    return data_.get() + size_;
  }
  // The text now ends at `end`, within the room() given last.
  void commit(char* end) { size_ = static_cast<std::size_t>(end - data_.get()); }

  std::string_view text() const { return {data_.get(), size_}; }
  void clear() { size_ = 0; }

 private:
  void grow(std::size_t bytes);

  std::unique_ptr<char[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

class OrderedText {
 public:
  // `threads`: 0 for all (core/parallel.h).
  OrderedText(std::ostream& out, int threads) : out_(out), threads_(threads) {}

  // Writes `text` after everything before it.
  void text(std::string_view text);

  // Writes blocks 0 .. count - 1 in order, block i's text made by format(i, block) (into an empty
  // block) on any thread: each block is written by the thread that finds it next due, while the
  // others format the following ones, at most a few blocks per thread ahead of the writing.
  // `format` must not throw.
  void blocks(std::size_t count, const std::function<void(std::size_t, TextBlock&)>& format);

 private:
  std::ostream& out_;
  int threads_;
  std::vector<TextBlock> spare_;  // blocks whose memory the next call reuses
};

}  // namespace uvtk::io
