// Outputs appear whole or not at all: a run interrupted by a signal while it writes, or stopped by a
// full disk or a file-size limit, or one of whose outputs cannot be written, leaves neither a
// partial output nor a temporary, and an output that existed before is untouched.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "apps/cli_test.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

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

  // Whether the folder's file system takes unnamed temporaries (O_TMPFILE), which nothing leaves behind.
  bool unnamedTemporaries() const {
    const int fd = ::open(dir_.c_str(), O_TMPFILE | O_WRONLY, 0600);
    if (fd >= 0) ::close(fd);
    return fd >= 0;
  }

  // Whether process `pid` writes a temporary output: a named one in the folder, or an unnamed one
  // open in it (/proc/PID/fd/N reads "FOLDER/#INODE (deleted)").
  bool temporaryExists(pid_t pid) const {
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
    std::error_code error;
    for (const auto& fd : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", error)) {
      const std::string target = fs::read_symlink(fd.path(), error).string();
      if (!error && target.rfind((dir_ / "#").string(), 0) == 0) return true;
    }
    return false;
  }

  // Whether process `pid` has a handler for `signal` (the SigCgt mask of /proc/PID/status).
  static bool catches(pid_t pid, int signal) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("SigCgt:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1;
    return false;
  }

  // Starts `PROGRAM ARGS...` (uvtk by default), waits until it has created a temporary output, sends
  // `signal`, and returns the raw wait status. Fails the test if no temporary appears within two minutes.
  int interruptWhileWriting(const std::vector<std::string>& arguments, int signal,
                            const std::string& program = UVTK_BINARY) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int err = ::open(path("stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      ::dup2(err, 2);
      const struct rlimit noCore {0, 0};  // SIGQUIT and SIGXCPU dump core by default
      ::setrlimit(RLIMIT_CORE, &noCore);
      // Started as from a shell: no signal ignored or blocked (a test runner may ignore SIGPIPE).
      for (int s = 1; s < NSIG; ++s) ::signal(s, SIG_DFL);
      // The signal ends it before any leak check could run; keep LeakSanitizer out of it all the same.
      const char* asan = std::getenv("ASAN_OPTIONS");
      ::setenv("ASAN_OPTIONS", (asan && *asan ? std::string(asan) + ":" : std::string()).append("detect_leaks=0").c_str(), 1);
      sigset_t none;
      sigemptyset(&none);
      ::sigprocmask(SIG_SETMASK, &none, nullptr);
      std::vector<char*> argv{const_cast<char*>(program.c_str())};
      for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(program.c_str(), argv.data());
      ::_exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    int status = 0;
    while (!temporaryExists(pid)) {
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
    // With unnamed temporaries the kernel removes them whatever ends the process; the handler that
    // removes named ones (the fallback, and the hidden names while publishing) must be there too.
    if (signal != SIGKILL) {
      EXPECT_TRUE(catches(pid, signal)) << "no handler for signal " << signal;
    }
    ::kill(pid, signal);
    ::waitpid(pid, &status, 0);
    return status;
  }
};

// Every signal whose default action ends the process, as `kill -QUIT` and the rest send them.
TEST_F(InterruptedOutput, EveryTerminatingSignalWhileWritingAnObjLeavesNothing) {
  writeInput(true);
  for (const int signal : {SIGINT, SIGTERM, SIGQUIT, SIGPIPE, SIGUSR1, SIGALRM, SIGXCPU}) {
    const int status =
        interruptWhileWriting({"map", path("in.obj"), "--projector", "sphere", "-o", path("out.obj")}, signal);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_EQ(outputsInFolder(), std::vector<std::string>{}) << "signal " << signal;
  }
}

// SIGKILL cannot be caught: only an unnamed temporary, which the kernel removes with the process,
// leaves nothing.
TEST_F(InterruptedOutput, SigkillWhileWritingAnObjLeavesNothingWithUnnamedTemporaries) {
  if (!unnamedTemporaries()) GTEST_SKIP() << "no O_TMPFILE in " << dir_ << ": a killed run leaves its temporary";
  writeInput(true);
  const int status = interruptWhileWriting(
      {"map", path("in.obj"), "--projector", "sphere", "-o", path("out.obj"), "--json", path("out.json")}, SIGKILL);
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{});
}

// Without /proc (hidden in a private mount namespace: root only) the temporary is a named file from
// the start, and the handler removes it.
TEST_F(InterruptedOutput, TheNamedTemporaryOfTheFallbackIsRemovedOnASignal) {
  if (::geteuid() != 0 || shell("unshare --mount sh -c 'mount -t tmpfs tmpfs /proc'").status != 0)
    GTEST_SKIP() << "hiding /proc needs root, unshare(1) and the right to mount";
  writeInput(true);
  const std::string map = uvtkCommand("map " + path("in.obj") + " --projector sphere -o " + path("out.obj"));
  // unshare execs sh, which execs uvtk: the signal reaches uvtk.
  const int status = interruptWhileWriting(
      {"--mount", "sh", "-c", "mount -t tmpfs tmpfs /proc && exec " + map}, SIGQUIT, "/usr/bin/unshare");
  ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status << ": " << readText(path("stderr.txt"));
  EXPECT_EQ(WTERMSIG(status), SIGQUIT);
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{});
}

// The outputs of one command are published together: when the last cannot be written, the first,
// already complete, does not appear either, and its previous version stays.
TEST_F(InterruptedOutput, AnOutputThatCannotBeWrittenLeavesTheOthersOut) {
  writeInput(false);
  const std::string report = "report " + path("in.obj") + " --projector sphere --size 32x32 --json " + path("r.json");
  CliRun r = uvtk(report + " --html " + path("missing/r.html"));
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_EQ(r.err.rfind(path("missing/r.html") + ": error: cannot write: ", 0), 0u) << r.err;
  EXPECT_EQ(outputsInFolder(), std::vector<std::string>{});

  const std::string before = "{\"previous\": true}\n";
  writeText("r.json", before);
  const auto written = fs::last_write_time(path("r.json"));
  fs::create_directory(path("r.html"));  // a folder where the page goes
  r = uvtk(report + " --html " + path("r.html"));
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_EQ(r.err, path("r.html") + ": error: cannot write: it is a folder\n");
  EXPECT_EQ(readText(path("r.json")), before);
  EXPECT_EQ(fs::last_write_time(path("r.json")), written);
  EXPECT_EQ(outputsInFolder(), (std::vector<std::string>{"r.html", "r.json"}));

  r = uvtk("map " + path("in.obj") + " --projector sphere -o " + path("out.obj") + " --json " + path("missing/s.json"));
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_EQ(outputsInFolder(), (std::vector<std::string>{"r.html", "r.json"}));
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
      shell(leakCheckOff() + "ulimit -f 8; exec " + uvtkCommand("map " + path("in.obj") + " --projector sphere -o " + path("kept.obj")));
  EXPECT_EQ(map.status, 4) << map.err;
  EXPECT_EQ(map.err, path("kept.obj") + ": error: cannot write: writing the temporary file failed: File too large\n");
  EXPECT_EQ(readText(path("kept.obj")), before);

  const CliRun render =
      shell(leakCheckOff() + "ulimit -f 8; exec " +
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

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
