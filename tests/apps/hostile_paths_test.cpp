// Hostile paths, through the program as a careless script meets them: an output that is a FIFO, a
// device, a symlink, a folder, standard output, a full disk, and two runs writing the same folder at
// once. Each must end with the right exit status and one line, replace no special file, write
// nothing outside the folder it names, and leave no temporary. (Signals: interrupted_output_test;
// scene paths that escape --output-dir: scene_paths_test.)
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "apps/cli_test.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class HostilePaths : public CliTest {
 protected:
  std::string cube() const { return std::string(UVTK_MESHES_DIR) + "/cube.obj"; }
  std::size_t cubeFaces() const { return io::readMesh(cube()).mesh.triangles.size(); }

  // Runs a shell command with stdout and stderr each captured.
  struct Captured {
    int status;
    std::string out, err;
  };
  Captured capture(const std::string& command) const {
    const int raw = std::system(("(" + command + ") > " + path("stdout.txt") + " 2> " + path("stderr.txt")).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readText(path("stdout.txt")), readText(path("stderr.txt"))};
  }

  // Every entry of the scratch folder and its subfolders whose name marks a temporary or a backup.
  std::vector<std::string> leftovers() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      const std::string name = entry.path().filename().string();
      if (name.find(".tmp.") != std::string::npos || name.find(".bak.") != std::string::npos) found.push_back(name);
    }
    return found;
  }

  static std::size_t lines(const std::string& text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }
};

TEST_F(HostilePaths, AFifoIsWrittenStraightAndStaysAFifo) {
  const std::string fifo = path("pipe.obj");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  // The reader runs beside uvtk, as `uvtk map ... -o >(gzip > x.gz)` would; it gives up after a
  // minute, so that a uvtk that never opens the pipe fails the test instead of hanging it.
  const CliRun run = shell("timeout 60 cat " + fifo + " > " + path("got.obj") + " & " + std::string(UVTK_BINARY) + " map " +
                           cube() + " --projector sphere -o " + fifo + " --quiet; status=$?; wait; exit $status");
  EXPECT_EQ(run.status, 0) << run.err;
  struct stat status {};
  ASSERT_EQ(::lstat(fifo.c_str(), &status), 0);
  EXPECT_TRUE(S_ISFIFO(status.st_mode));
  // What the reader got is the whole mesh: it reads back with the cube's triangles.
  EXPECT_EQ(io::readMesh(path("got.obj")).mesh.triangles.size(), cubeFaces());
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(HostilePaths, ACharacterDeviceIsWrittenAndNeverReplaced) {
  // /dev/full takes no byte: exit 4 with the reason, and it is still the same device.
  struct stat before {}, after {};
  if (::stat("/dev/full", &before) != 0 || !S_ISCHR(before.st_mode)) GTEST_SKIP() << "no /dev/full";
  const CliRun full = uvtk("map " + cube() + " --projector sphere -o /dev/full --quiet");
  EXPECT_EQ(full.status, 4);
  EXPECT_NE(full.err.find("/dev/full: error: cannot write"), std::string::npos) << full.err;
  EXPECT_NE(full.err.find("No space left on device"), std::string::npos) << full.err;
  EXPECT_EQ(lines(full.err), 1u) << full.err;
  ASSERT_EQ(::stat("/dev/full", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_ino, before.st_ino);
  EXPECT_EQ(after.st_rdev, before.st_rdev);

  // A null device of our own (root only: mknod), so that replacing it would show and harm nothing.
  const std::string null = path("null");
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs root";
  ASSERT_EQ(::stat(null.c_str(), &before), 0);
  const CliRun run = uvtk("map " + cube() + " --projector sphere -o " + null + " --json " + null + " --quiet");
  EXPECT_EQ(run.status, 0) << run.err;
  ASSERT_EQ(::stat(null.c_str(), &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_ino, before.st_ino);
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(HostilePaths, ASymlinkIsFollowedAndKept) {
  fs::create_directories(path("real"));
  writeText("real/target.obj", "old\n");
  fs::create_symlink("real/target.obj", path("link.obj"));
  const CliRun run = uvtk("map " + cube() + " --projector sphere -o " + path("link.obj") + " --quiet");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::is_symlink(path("link.obj")));
  EXPECT_EQ(io::readMesh(path("real/target.obj")).mesh.triangles.size(), cubeFaces());
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(HostilePaths, AFolderAsTheOutputIsRefusedBeforeAnyWork) {
  fs::create_directories(path("out.obj"));
  const CliRun run = uvtk("map " + cube() + " --projector sphere -o " + path("out.obj") + " --quiet");
  EXPECT_EQ(run.status, 4);
  EXPECT_EQ(run.err, path("out.obj") + ": error: cannot write: it is a folder\n");
  EXPECT_TRUE(fs::is_directory(path("out.obj")));
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(HostilePaths, DashIsStandardOutputAndTheSummaryMovesToStderr) {
  const Captured run = capture(std::string(UVTK_BINARY) + " map " + cube() + " --projector sphere -o - --json " +
                               path("s.json"));
  EXPECT_EQ(run.status, 0) << run.err;
  // stdout holds the OBJ and nothing else; the summary line is on stderr.
  EXPECT_EQ(run.out.rfind("# ", 0) == 0 || run.out.rfind("v ", 0) == 0 || run.out.rfind("mtllib", 0) == 0, true)
      << run.out.substr(0, 80);
  EXPECT_EQ(run.out.find("uvtk map:"), std::string::npos);
  EXPECT_NE(run.err.find("uvtk map:"), std::string::npos) << run.err;
  writeText("back.obj", run.out);
  EXPECT_EQ(io::readMesh(path("back.obj")).mesh.triangles.size(), cubeFaces());
  EXPECT_TRUE(fs::exists(path("s.json")));

  // A failing second output: nothing at all reaches stdout.
  const Captured failed = capture(std::string(UVTK_BINARY) + " map " + cube() + " --projector sphere -o - --json " +
                                  path("missing/s.json"));
  EXPECT_EQ(failed.status, 4) << failed.err;
  EXPECT_EQ(failed.out, "");
  EXPECT_EQ(lines(failed.err), 1u) << failed.err;
}

TEST_F(HostilePaths, AReportOnAFullDiskLeavesNeitherOfItsOutputs) {
  const std::string small = path("small");
  fs::create_directories(small);
  if (::geteuid() != 0 || shell("unshare --mount sh -c 'mount -t tmpfs -o size=64k tmpfs " + small + "'").status != 0)
    GTEST_SKIP() << "mounting a small tmpfs needs root, unshare(1) and the right to mount";
  // The JSON (a few KB) fits; the HTML with its pictures does not.
  const std::string report = std::string(UVTK_BINARY) + " report " + cube() + " --projector sphere --json " + small +
                             "/r.json --html " + small + "/r.html";
  const CliRun run = shell("unshare --mount sh -c 'mount -t tmpfs -o size=64k tmpfs " + small + " && " + report +
                           "; status=$?; ls -A " + small + " > " + path("listing.txt") + "; exit $status'");
  EXPECT_EQ(run.status, 4) << run.err;
  EXPECT_NE(run.err.find("No space left on device"), std::string::npos) << run.err;
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_EQ(readText(path("listing.txt")), "");  // neither r.json nor any temporary
}

TEST_F(HostilePaths, AMeshTooLargeToMapIsRefusedBeforeItIsRead) {
  if (kAddressSanitized) GTEST_SKIP() << "the sanitizers reserve terabytes of address space, which ulimit -v forbids";
  // A sparse 4 GiB file: a map of it would take about 12 GiB, more than 3 GB of address space.
  const std::string big = path("big.obj");
  { std::ofstream(big, std::ios::binary) << "v 0 0 0\n"; }
  fs::resize_file(big, std::uintmax_t(4) << 30);
  const CliRun run = shell("ulimit -v 3000000; " + std::string(UVTK_BINARY) + " map " + big + " -o " +
                           path("out.obj") + " --quiet");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(run.err.find(big + ": error: mapping it needs about 12.0 GiB of memory, more than the "), 0u) << run.err;
  EXPECT_EQ(lines(run.err), 1u) << run.err;
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(HostilePaths, TwoRunsOfOneSceneIntoOneFolderLeaveEveryOutputWhole) {
  // A mesh large enough that both runs write at the same time.
  const Mesh knot = meshes::torusKnot(2, 3, 400, 24);
  io::writeObj(path("knot.obj"), knot, nullptr);
  writeText("scene.json", R"({
  "meshes": [{"name": "knot", "path": "knot.obj", "mappings": [{"kind": "projector", "name": "s", "projector": "sphere"}]}],
  "outputs": [{"kind": "obj", "mapping": "s", "path": "knot_s.obj", "json": "knot_s.json"}]
})");
  const std::string run = std::string(UVTK_BINARY) + " run " + path("scene.json") + " --output-dir " + path("out") +
                          " --quiet";
  for (int round = 0; round < 3; ++round) {
    const CliRun both = shell(run + " & " + run + "; a=$?; wait $!; b=$?; exit $((a | b))");
    ASSERT_EQ(both.status, 0) << both.err;
    EXPECT_EQ(io::readMesh(path("out/knot_s.obj")).mesh.triangles.size(), knot.triangles.size());
    const std::string json = readText(path("out/knot_s.json"));
    ASSERT_FALSE(json.empty());
    EXPECT_EQ(json.back(), '\n');
    EXPECT_TRUE(leftovers().empty());
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
