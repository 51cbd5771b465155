#include "io/temporary_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class TemporaryFileTest : public ScratchDirTest {
 protected:
  // The names in the scratch folder, sorted (hidden ones too).
  std::vector<std::string> names() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir_)) found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    return found;
  }
  static void writeTo(const TemporaryFile& file, const std::string& text) {
    std::ofstream out(file.path(), std::ios::binary | std::ios::trunc);
    out << text;
    ASSERT_TRUE(out.flush()) << file.path();
  }
  // Whether this folder's file system takes O_TMPFILE (ext4, xfs, btrfs, tmpfs do).
  bool unnamedTemporaries() const {
    const int fd = ::open(dir_.c_str(), O_TMPFILE | O_WRONLY, 0600);
    if (fd >= 0) ::close(fd);
    return fd >= 0;
  }
  static mode_t newFileMode() {
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
  }
};

TEST_F(TemporaryFileTest, IsUnnamedWhileWrittenAndGetsANewFilesModeWhenCommitted) {
  if (!unnamedTemporaries()) GTEST_SKIP() << "no O_TMPFILE in " << dir_;
  TemporaryFile temporary(path("out.png"));
  EXPECT_EQ(temporary.path().rfind("/proc/self/fd/", 0), 0u) << temporary.path();
  writeTo(temporary, "whole");
  EXPECT_EQ(names(), std::vector<std::string>{}) << "no name in the folder while it is written";
  temporary.commit();
  EXPECT_EQ(names(), std::vector<std::string>{"out.png"});
  EXPECT_EQ(readText(path("out.png")), "whole");
  struct stat status {};
  ASSERT_EQ(::stat(path("out.png").c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, newFileMode());
}

TEST_F(TemporaryFileTest, IsRemovedUnlessCommittedAndCommitReplacesTheTarget) {
  writeText("b.txt", "previous");
  { TemporaryFile discarded(path("a.txt")); writeTo(discarded, "never seen"); }
  EXPECT_EQ(names(), std::vector<std::string>{"b.txt"});
  TemporaryFile temporary(path("b.txt"));
  writeTo(temporary, "whole");
  EXPECT_EQ(readText(path("b.txt")), "previous");
  temporary.commit();
  EXPECT_EQ(readText(path("b.txt")), "whole");
  EXPECT_EQ(names(), std::vector<std::string>{"b.txt"});
}

TEST_F(TemporaryFileTest, MoreOutputsThanTheSignalTableHoldsStillPublish) {
  // The handler's table has 256 slots; at publish every output takes one for its hidden name.
  std::vector<std::unique_ptr<TemporaryFile>> many;
  std::vector<TemporaryFile*> files;
  for (int i = 0; i < 300; ++i) {
    many.push_back(std::make_unique<TemporaryFile>(path("f" + std::to_string(i))));
    writeTo(*many.back(), std::to_string(i));
    files.push_back(many.back().get());
  }
  publishTogether(files);
  many.clear();
  EXPECT_EQ(names().size(), 300u);
  EXPECT_EQ(readText(path("f299")), "299");
  for (const std::string& name : names()) EXPECT_NE(name[0], '.') << name;
}

TEST_F(TemporaryFileTest, AMissingFolderIsAnOutputErrorNamingTheTarget) {
  const std::string target = path("no/such/out.obj");
  try {
    TemporaryFile temporary(target);
    ADD_FAILURE() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()),
              target + ": error: cannot write: cannot create a temporary file beside it: No such file or directory");
  }
}

TEST_F(TemporaryFileTest, AFolderIsRefusedBeforeAnythingIsWritten) {
  fs::create_directory(path("out.obj"));
  try {
    TemporaryFile temporary(path("out.obj"));
    ADD_FAILURE() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()), path("out.obj") + ": error: cannot write: it is a folder");
  }
  EXPECT_TRUE(fs::is_directory(path("out.obj")));
}

TEST_F(TemporaryFileTest, ASymlinkIsKeptAndTheFileItLeadsToIsReplaced) {
  writeText("real.txt", "previous");
  fs::create_symlink("real.txt", path("link.txt"));
  writeFileAtomically(path("link.txt"), "new");
  EXPECT_TRUE(fs::is_symlink(path("link.txt")));
  EXPECT_EQ(fs::read_symlink(path("link.txt")), "real.txt");
  EXPECT_EQ(readText(path("real.txt")), "new");
  EXPECT_EQ(names(), (std::vector<std::string>{"link.txt", "real.txt"}));
}

TEST_F(TemporaryFileTest, ADanglingSymlinkCreatesTheFileItNames) {
  fs::create_symlink("made.txt", path("dangling.txt"));
  writeFileAtomically(path("dangling.txt"), "created");
  EXPECT_TRUE(fs::is_symlink(path("dangling.txt")));
  EXPECT_EQ(readText(path("made.txt")), "created");
  EXPECT_EQ(names(), (std::vector<std::string>{"dangling.txt", "made.txt"}));
}

TEST_F(TemporaryFileTest, AChainOfRelativeSymlinksIsFollowedToItsEnd) {
  // first.txt -> sub/second.txt -> ../end.txt (relative to sub/, so the scratch folder's end.txt).
  fs::create_directory(path("sub"));
  writeText("end.txt", "previous");
  fs::create_symlink("../end.txt", path("sub/second.txt"));
  fs::create_symlink("sub/second.txt", path("first.txt"));
  writeFileAtomically(path("first.txt"), "through two links");
  EXPECT_TRUE(fs::is_symlink(path("first.txt")));
  EXPECT_TRUE(fs::is_symlink(path("sub/second.txt")));
  EXPECT_EQ(readText(path("end.txt")), "through two links");
  EXPECT_EQ(names(), (std::vector<std::string>{"end.txt", "first.txt", "sub"}));
  EXPECT_EQ(std::distance(fs::directory_iterator(path("sub")), {}), 1);
}

TEST_F(TemporaryFileTest, ALoopOfSymlinksIsAnOutputError) {
  fs::create_symlink("b", path("a"));
  fs::create_symlink("a", path("b"));
  EXPECT_THROW(writeFileAtomically(path("a"), "x"), OutputError);
  EXPECT_EQ(names(), (std::vector<std::string>{"a", "b"}));
}

TEST_F(TemporaryFileTest, AFifoIsWrittenStraightAndStaysAFifo) {
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = readText(path("pipe")); });
  writeFileAtomically(path("pipe"), "through the pipe\n");
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(path("pipe")));
  EXPECT_EQ(names(), std::vector<std::string>{"pipe"});
}

TEST_F(TemporaryFileTest, ACharacterDeviceIsWrittenStraightAndNeverReplaced) {
  // A null device of our own when we may make one (root); else /dev/null itself, only written,
  // which is what this test makes sure of.
  std::string device = path("null");
  if (::mknod(device.c_str(), S_IFCHR | 0666, ::makedev(1, 3)) != 0) device = "/dev/null";
  struct stat before {};
  ASSERT_EQ(::stat(device.c_str(), &before), 0);
  if (!S_ISCHR(before.st_mode) || ::access(device.c_str(), W_OK) != 0)
    GTEST_SKIP() << device << " is not a writable character device";
  writeFileAtomically(device, "into nothing");
  struct stat after {};
  ASSERT_EQ(::stat(device.c_str(), &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_rdev, before.st_rdev);
  EXPECT_EQ(after.st_ino, before.st_ino) << "the node was replaced";
  if (device != "/dev/null") EXPECT_EQ(names(), std::vector<std::string>{"null"});
  else EXPECT_EQ(names(), std::vector<std::string>{});
}

// Runs `write` with fd 1 sent to a file; returns what reached it.
template <typename Write>
std::string capturedStdout(const std::string& file, Write write) {
  std::fflush(stdout);
  const int saved = ::dup(1);
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(fd, 1);
  ::close(fd);
  try {
    write();
  } catch (...) {
    ::dup2(saved, 1);
    ::close(saved);
    throw;
  }
  ::dup2(saved, 1);
  ::close(saved);
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST_F(TemporaryFileTest, DashIsStandardOutputWrittenWhenPublished) {
  const std::string captured = path("stdout.txt");
  std::string seenBefore;
  const std::string got = capturedStdout(captured, [&] {
    AtomicFile file("-");
    file.stream() << "line one\nline two\n";
    file.stream().flush();
    seenBefore = readText(captured);  // staged: nothing on stdout yet
    file.commit();
  });
  EXPECT_EQ(seenBefore, "");
  EXPECT_EQ(got, "line one\nline two\n");
  EXPECT_TRUE(stdoutIsAnOutput());
  EXPECT_EQ(names(), std::vector<std::string>{"stdout.txt"});
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
