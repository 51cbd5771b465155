// Every failure has its class and one readable line: the standard library's exceptions that input
// or the machine cause map to exit statuses, and names with control characters are escaped.
#include "core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <new>
#include <system_error>

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

TEST(ExitStatus, ClassesOursAndTheStandardLibrarysExceptions) {
  EXPECT_EQ(exitStatus(UsageError("u")), 2);
  EXPECT_EQ(exitStatus(InputError("i")), 3);
  EXPECT_EQ(exitStatus(OutputError("o")), 4);
  EXPECT_EQ(exitStatus(std::bad_alloc()), 3);
  EXPECT_EQ(exitStatus(std::length_error("vector::reserve")), 3);
  const std::filesystem::filesystem_error tooLong("weakly_canonical", "a/b",
                                                   std::make_error_code(std::errc::filename_too_long));
  EXPECT_EQ(exitStatus(tooLong), 3);
  EXPECT_EQ(exitStatus(std::logic_error("a bug")), 1);
  EXPECT_EQ(exitStatus(std::runtime_error("a bug")), 1);
}

TEST(ErrorMessage, IsOneLineInUvtksWords) {
  EXPECT_EQ(errorMessage(std::bad_alloc()),
            "uvtk: error: out of memory: the work needs more memory than the machine has or ulimit -v allows");
  const std::filesystem::filesystem_error tooLong("weakly_canonical", std::string("a\tb"),
                                                   std::make_error_code(std::errc::filename_too_long));
  EXPECT_EQ(errorMessage(tooLong), "a\\tb: error: File name too long");
  EXPECT_EQ(errorMessage(InputError("x.obj:3: error: expected \x1b[31m")), "x.obj:3: error: expected \\u001b[31m");
}

TEST(Printable, EscapesControlCharactersButTheLineFeed) {
  EXPECT_EQ(printable("plain name.obj"), "plain name.obj");
  EXPECT_EQ(printable(std::string("a\0b\r\t\x7f\nc", 8)), "a\\u0000b\\r\\t\\u007f\nc");
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9") << "UTF-8 stays as it is";
}

TEST(QuotedName, IsAJsonStringThatKeepsEveryByte) {
  EXPECT_EQ(quotedName("out/x.obj"), "\"out/x.obj\"");
  EXPECT_EQ(quotedName(std::string("a\0b\"\\\n", 6)), "\"a\\u0000b\\\"\\\\\\n\"");
  EXPECT_EQ(quotedName(""), "\"\"");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
