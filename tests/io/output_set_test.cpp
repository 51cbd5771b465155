// The outputs of one command appear together or not at all.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class OutputSetTest : public ScratchDirTest {
 protected:
  std::vector<std::string> names(const std::string& folder = "") const {
    std::vector<std::string> found;
    for (const auto& entry : fs::directory_iterator(folder.empty() ? dir_ : fs::path(path(folder))))
      found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    return found;
  }
};

TEST_F(OutputSetTest, NothingAppearsUntilPublishThenEverything) {
  writeText("a.json", "old a");
  OutputSet outputs;
  outputs.writeText(path("a.json"), "new a");
  outputs.writeText(path("b.html"), "new b");
  Image image(4, 2, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i % 3) / 2.0f;
  writeImage(outputs, path("c.png"), image, PixelType::UInt8);
  Mesh triangle;
  triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.triangles = {{0, 1, 2}};
  writeObj(outputs, path("d.obj"), triangle, nullptr);
  for (const std::string& name : names()) EXPECT_TRUE(name == "a.json" || name[0] == '.') << name;
  EXPECT_EQ(readText(path("a.json")), "old a");

  outputs.publish();
  EXPECT_EQ(names(), (std::vector<std::string>{"a.json", "b.html", "c.png", "d.obj"}));
  EXPECT_EQ(readText(path("a.json")), "new a");
  EXPECT_EQ(readText(path("b.html")), "new b");
  const ImageFile read = readImage(path("c.png"));
  EXPECT_EQ(read.image.width, 4);
  EXPECT_FLOAT_EQ(read.image.pixels[2], 1.0f);
  EXPECT_EQ(readMesh(path("d.obj")).mesh.faceCount(), 1u);
}

TEST_F(OutputSetTest, WhatIsNotPublishedIsDiscarded) {
  writeText("kept.txt", "previous");
  {
    OutputSet outputs;
    outputs.writeText(path("kept.txt"), "never");
    outputs.writeText(path("new.txt"), "never");
  }
  EXPECT_EQ(names(), std::vector<std::string>{"kept.txt"});
  EXPECT_EQ(readText(path("kept.txt")), "previous");
}

// `uvtk report --json r.json --html DIR_THAT_FAILS/r.html`: the second output fails while it is
// staged, so the first, already written, never appears.
TEST_F(OutputSetTest, AnOutputThatCannotBeStagedLeavesNone) {
  writeText("r.json", "previous");
  EXPECT_THROW(
      {
        OutputSet outputs;
        outputs.writeText(path("r.json"), "new");
        outputs.writeText(path("missing/r.html"), "new");
        outputs.publish();
      },
      OutputError);
  EXPECT_EQ(names(), std::vector<std::string>{"r.json"});
  EXPECT_EQ(readText(path("r.json")), "previous");
}

// The second rename fails after the first target was replaced: the first is put back.
TEST_F(OutputSetTest, AFailingRenameUndoesTheTargetsAlreadyReplaced) {
  for (const bool existedBefore : {true, false}) {
    SCOPED_TRACE(existedBefore ? "a.txt existed" : "a.txt is new");
    fs::remove_all(path("a.txt"));
    fs::remove_all(path("b.txt"));
    if (existedBefore) writeText("a.txt", "previous a");
    {
      OutputSet outputs;
      outputs.writeText(path("a.txt"), "new a");
      outputs.writeText(path("b.txt"), "new b");
      fs::create_directory(path("b.txt"));  // a folder arrives where b goes: its rename fails
      writeText("b.txt/inside", "x");
      try {
        outputs.publish();
        ADD_FAILURE() << "no OutputError";
      } catch (const OutputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path("b.txt") + ": error: cannot write: cannot rename the temporary "
                                                              "file onto it: ",
                                              0),
                  0u)
            << e.what();
      }
      if (existedBefore) {
        EXPECT_EQ(readText(path("a.txt")), "previous a");
      }
    }  // the set, failed, is discarded with its temporaries
    if (existedBefore) {
      EXPECT_EQ(names(), (std::vector<std::string>{"a.txt", "b.txt"}));
      EXPECT_EQ(readText(path("a.txt")), "previous a");
    } else {
      EXPECT_EQ(names(), std::vector<std::string>{"b.txt"});
    }
    EXPECT_EQ(names("b.txt"), std::vector<std::string>{"inside"});
  }
  EXPECT_EQ(names(), std::vector<std::string>{"b.txt"}) << "no backup or temporary is left";
}

// Not as root, who writes into a read-only folder anyway.
TEST_F(OutputSetTest, AFolderMadeReadOnlyBeforePublishLeavesNone) {
  withoutPrivileges(dir_, [&] {  // root writes into read-only folders
    fs::create_directory(path("locked"));
    writeText("a.txt", "previous a");
    writeText("locked/b.txt", "previous b");
    {
      OutputSet outputs;
      outputs.writeText(path("a.txt"), "new a");
      outputs.writeText(path("locked/b.txt"), "new b");
      fs::permissions(path("locked"), fs::perms::owner_read | fs::perms::owner_exec);
      EXPECT_THROW(outputs.publish(), OutputError);
      EXPECT_EQ(readText(path("a.txt")), "previous a");
    }
    fs::permissions(path("locked"), fs::perms::owner_all);
    EXPECT_EQ(names(), (std::vector<std::string>{"a.txt", "locked"}));
    EXPECT_EQ(names("locked"), std::vector<std::string>{"b.txt"});
    EXPECT_EQ(readText(path("a.txt")), "previous a");
    EXPECT_EQ(readText(path("locked/b.txt")), "previous b");
  });
}

TEST_F(OutputSetTest, AdoptedOutputsArePublishedWithTheSet) {
  OutputSet all, part;
  all.writeText(path("first.txt"), "1");
  part.writeText(path("second.txt"), "2");
  all.adopt(part);
  part.publish();  // now empty: publishes nothing
  for (const std::string& name : names()) EXPECT_EQ(name[0], '.') << "only unpublished temporaries: " << name;
  all.publish();
  EXPECT_EQ(names(), (std::vector<std::string>{"first.txt", "second.txt"}));
}

// When publishing fails, nothing half-written (or whole) reaches standard output either.
TEST_F(OutputSetTest, StandardOutputGetsNothingWhenTheSetFails) {
  std::fflush(stdout);
  const int saved = ::dup(1);
  const int fd = ::open(path("stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(fd, 1);
  ::close(fd);
  bool failed = false;
  {
    OutputSet outputs;
    outputs.writeText("-", "the table\n");
    outputs.writeText(path("b.txt"), "new b");
    fs::create_directory(path("b.txt"));
    writeText("b.txt/inside", "x");
    try {
      outputs.publish();
    } catch (const OutputError&) {
      failed = true;
    }
  }
  {
    OutputSet outputs;
    outputs.writeText("-", "published\n");
    outputs.writeText(path("c.txt"), "c");
    outputs.publish();
  }
  ::dup2(saved, 1);
  ::close(saved);
  EXPECT_TRUE(failed);
  EXPECT_EQ(readText(path("stdout.txt")), "published\n");
  EXPECT_EQ(readText(path("c.txt")), "c");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
