#include "io/checksum.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using ChecksumTest = ScratchDirTest;

// FIPS 180-2's examples, and a file longer than one 64 KiB read.
TEST_F(ChecksumTest, Sha256OfKnownFiles) {
  EXPECT_EQ(sha256File(writeText("empty", "")), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256File(writeText("abc", "abc")), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256File(writeText("million", std::string(1000000, 'a'))),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_F(ChecksumTest, AMissingFileIsAnInputError) {
  EXPECT_THROW(sha256File(path("missing")), InputError);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
