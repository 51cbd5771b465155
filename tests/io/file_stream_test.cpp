// The stream outputs are written through (io/file_stream.h): every byte in order, whatever the
// mix of small and large writes and the write-back started along the way; the first failure kept
// with its reason; truncation only when asked.
#include "io/file_stream.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <string>

#include "io/atomic_file.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

class FileStreamTest : public ScratchDirTest {};

// 20 MiB and a little: past two write-back steps of 8 MiB, in pieces of every size.
std::string writeMixed(std::ostream& out) {
  std::string expected;
  std::string block(3 << 20, ' ');
  for (std::size_t i = 0; i < block.size(); ++i) block[i] = char('a' + i % 23);
  for (int round = 0; round < 7; ++round) {
    out << "line " << round << '\n';
    expected += "line " + std::to_string(round) + "\n";
    out.put('x');
    expected += 'x';
    out.write(block.data(), std::streamsize(block.size() - std::size_t(round)));  // larger than the buffer
    expected.append(block, 0, block.size() - std::size_t(round));
    out.write(block.data(), 1000);  // fits in it
    expected.append(block, 0, 1000);
  }
  return expected;
}

TEST_F(FileStreamTest, EveryByteArrivesInOrder) {
  const std::string file = path("out.txt");
  FileStream stream(file, true);
  ASSERT_TRUE(stream);
  const std::string expected = writeMixed(stream);
  EXPECT_TRUE(stream.close());
  EXPECT_EQ(stream.error(), 0);
  EXPECT_EQ(std::filesystem::file_size(file), expected.size());
  EXPECT_TRUE(readText(file) == expected);
}

TEST_F(FileStreamTest, TruncatesOnlyWhenAsked) {
  const std::string file = writeText("old.txt", "abcdef");
  {
    FileStream stream(file, false);
    stream << "XY";
    EXPECT_TRUE(stream.close());
  }
  EXPECT_EQ(readText(file), "XYcdef");
  {
    FileStream stream(file, true);
    stream << "XY";
  }  // closed by its destructor
  EXPECT_EQ(readText(file), "XY");
}

TEST_F(FileStreamTest, AFailedWriteIsKeptWithItsReason) {
  ASSERT_TRUE(std::filesystem::exists("/dev/full"));  // Linux's always-full device
  FileStream stream("/dev/full", true);
  ASSERT_TRUE(stream);
  const std::string block(1 << 17, 'z');
  stream.write(block.data(), std::streamsize(block.size()));
  EXPECT_FALSE(stream);
  stream << "more";  // written no more
  EXPECT_FALSE(stream.close());
  EXPECT_EQ(stream.error(), ENOSPC);
}

TEST_F(FileStreamTest, AFileThatCannotBeOpenedSaysWhy) {
  FileStream stream(path("missing/out.txt"), true);
  EXPECT_FALSE(stream);
  EXPECT_EQ(stream.error(), ENOENT);
  EXPECT_FALSE(stream.close());
}

TEST_F(FileStreamTest, ALargeOutputOfASetArrivesWhole) {
  writeText("big.txt", "the previous version");
  OutputSet outputs;
  std::string expected;
  outputs.write(path("big.txt"), [&](std::ostream& out) { expected = writeMixed(out); });
  EXPECT_EQ(readText(path("big.txt")), "the previous version");
  outputs.publish();
  EXPECT_TRUE(readText(path("big.txt")) == expected);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
