#include "io/temporary_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {

namespace fs = std::filesystem;

using TemporaryFileTest = ScratchDirTest;

TEST_F(TemporaryFileTest, IsAHiddenFileBesideTheTargetThatKeepsItsExtension) {
  TemporaryFile temporary(path("out.png"));
  const fs::path p(temporary.path());
  EXPECT_EQ(p.parent_path(), dir_);
  const std::string name = p.filename().string();
  EXPECT_EQ(name.rfind(".out.png.tmp.", 0), 0u) << name;
  EXPECT_EQ(p.extension(), ".png");
  EXPECT_EQ(name.size(), std::string(".out.png.tmp.XXXXXX.png").size());
  EXPECT_TRUE(fs::exists(p));
}

TEST_F(TemporaryFileTest, IsRemovedUnlessCommittedAndCommitRenamesItOntoTheTarget) {
  std::string left;
  {
    TemporaryFile temporary(path("a.txt"));
    left = temporary.path();
  }
  EXPECT_FALSE(fs::exists(left));
  TemporaryFile temporary(path("b.txt"));
  writeText(fs::path(temporary.path()).filename().string(), "whole");
  temporary.commit();
  EXPECT_EQ(readText(path("b.txt")), "whole");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 1);
}

TEST_F(TemporaryFileTest, MoreTemporariesThanTheSignalTableHoldsStillWork) {
  // The handler's table has 256 slots; the ones beyond it are created and removed all the same.
  std::vector<std::unique_ptr<TemporaryFile>> many;
  for (int i = 0; i < 300; ++i) many.push_back(std::make_unique<TemporaryFile>(path("f" + std::to_string(i))));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 300);
  many.clear();
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 0);
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

}  // namespace
}  // namespace uvtk::io
