// Outputs appear whole or not at all: a run interrupted by a signal while it writes, or stopped by a
// full disk or a file-size limit, leaves neither a partial output nor a temporary, and an output
// that existed before is untouched.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "apps/cli_test.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {

namespace fs = std::filesystem;

class InterruptedOutput : public CliTest {
 protected:
  // The input "in.obj": `large`, about 1 M faces, takes long enough to write that a signal lands
  // mid-write; the other, 16 K faces, still writes more than the limits below (8 KiB, a 256 KiB disk).
  void writeInput(bool large) const {
    io::writeObj(path("in.obj"), large ? meshes::latLongSphere(1024, 512) : meshes::latLongSphere(128, 64), nullptr);
  }

  // The folder's entries other than the input, sorted.
  std::vector<std::string> outputsInFolder() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (name != "in.obj" && name != "stderr.txt" && name != "listing.txt" && name != "small") names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  static std::string uvtkCommand(const std::string& arguments) { return std::string(UVTK_BINARY) + " " + arguments; }

  bool temporaryExists() const {
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
    return false;
  }

  // Starts `uvtk ARGS...`, waits until it has created a temporary output, sends `signal`, and
  // returns the raw wait status. Fails the test if no temporary appears within two minutes.
  int interruptWhileWriting(const std::vector<std::string>& arguments, int signal) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int err = ::open(path("stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(err, 2);
      std::vector<char*> argv{const_cast<char*>(UVTK_BINARY)};
      for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(UVTK_BINARY, argv.data());
      ::_exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    int status = 0;
    while (!temporaryExists()) {
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        ADD_FAILURE() << "uvtk ended before it wrote a temporary: " << readText(path("stderr.txt"));
        return status;
      }
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(pid, SIGKILL);
        ADD_FAILURE() << "no temporary appeared within two minutes";
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ::kill(pid, signal);
    ::waitpid(pid, &status, 0);
    return status;
  }
};

TEST_F(InterruptedOutput, SigintAndSigtermWhileWritingAnObjLeaveNothing) {
  writeInput(true);
  for (const int signal : {SIGINT, SIGTERM}) {
    const int status =
        interruptWhileWriting({"map", path("in.obj"), "--projector", "sphere", "-o", path("out.obj")}, signal);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_EQ(outputsInFolder(), std::vector<std::string>{}) << "signal " << signal;
  }
}

TEST_F(InterruptedOutput, AnInterruptedRunLeavesTheExistingOutputAsItWas) {
  writeInput(true);
  const std::string before = "# the previous output\n";
  writeText("out.obj", before);
  const auto written = fs::last_write_time(path("out.obj"));
  const int status =
      interruptWhileWriting({"map", path("in.obj"), "--projector", "cylinder", "-o", path("out.obj")}, SIGTERM);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{"out.obj"});
  EXPECT_EQ(readText(path("out.obj")), before);
  EXPECT_EQ(fs::last_write_time(path("out.obj")), written);
}

TEST_F(InterruptedOutput, SigintWhileWritingAPictureLeavesNothing) {
  writeInput(false);  // the picture's size makes the write long
  const int status = interruptWhileWriting(
      {"render", path("in.obj"), "--projector", "sphere", "--size", "4096x4096", "-o", path("out.exr")}, SIGINT);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGINT);
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{});
}

// A file-size limit (ulimit -f, in KiB) makes writes fail with EFBIG, as a full disk fails them with ENOSPC.
TEST_F(InterruptedOutput, AFileSizeLimitIsAWriteErrorThatLeavesNothing) {
  writeInput(false);
  const std::string before = "# the previous output\n";
  writeText("kept.obj", before);
  const CliRun map =
      shell("ulimit -f 8; exec " + uvtkCommand("map " + path("in.obj") + " --projector sphere -o " + path("kept.obj")));
  EXPECT_EQ(map.status, 4) << map.err;
  EXPECT_EQ(map.err, path("kept.obj") + ": error: cannot write: writing the temporary file failed: File too large\n");
  EXPECT_EQ(readText(path("kept.obj")), before);

  const CliRun render =
      shell("ulimit -f 8; exec " +
            uvtkCommand("render " + path("in.obj") + " --projector sphere --size 1024x1024 -o " + path("p.exr")));
  EXPECT_EQ(render.status, 4) << render.err;
  EXPECT_EQ(render.err.rfind(path("p.exr") + ": error: cannot write: ", 0), 0u) << render.err;
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{"kept.obj"});
}

// A real full disk: a 256 KiB tmpfs mounted in a private mount namespace (needs root; skipped otherwise).
TEST_F(InterruptedOutput, AFullDiskIsAWriteErrorThatLeavesNothing) {
  fs::create_directory(path("small"));
  const std::string small = path("small");
  if (::geteuid() != 0 || shell("unshare --mount sh -c 'mount -t tmpfs -o size=256k tmpfs " + small + "'").status != 0)
    GTEST_SKIP() << "mounting a small tmpfs needs root, unshare(1) and the right to mount; the file-size limit test "
                    "covers EFBIG";
  writeInput(false);
  const CliRun run = shell("unshare --mount sh -c 'mount -t tmpfs -o size=256k tmpfs " + small + " && " +
                           uvtkCommand("map " + path("in.obj") + " --projector sphere -o " + small + "/out.obj") +
                           "; status=$?; ls -A " + small + " > " + path("listing.txt") + "; exit $status'");
  EXPECT_EQ(run.status, 4) << run.err;
  EXPECT_EQ(run.err,
            small + "/out.obj: error: cannot write: writing the temporary file failed: No space left on device\n");
  EXPECT_EQ(readText(path("listing.txt")), "");
}

}  // namespace
}  // namespace uvtk
