// A fresh folder per test under the system's temporary folder, removed afterwards.
#pragma once

#include <grp.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <functional>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace uvtk {

// Runs `body` without root's power to read and write any file, so that a test of a refused
// permission runs as root too: when the test runs as root, in a child that gives root up (user and
// group 65534, nobody) and owns `folder`; else here. The child's failures fail the test.
inline void withoutPrivileges(const std::filesystem::path& folder, const std::function<void()>& body) {
  if (::geteuid() != 0) return body();
  constexpr unsigned kNobody = 65534;
  ASSERT_EQ(::chown(folder.c_str(), kNobody, kNobody), 0);
  std::fflush(nullptr);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    if (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0) ::_exit(3);
    body();
    std::fflush(nullptr);
    ::_exit(::testing::Test::HasFailure() ? 1 : 0);  // no exit handlers: the parent's objects stay its own
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "the child without root's privileges failed (its messages are above), wait status " << status;
}

class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("uvtk_" + std::to_string(::getpid()) + "_" + test->test_suite_name() + "_" + test->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;  // a test may have left a file unreadable
    // Not through a symbolic link: chmod follows it, and a link to /dev/null left it 0700 for everyone.
    for (const auto& entry : std::filesystem::directory_iterator(dir_, ignored))
      if (!entry.is_symlink(ignored)) std::filesystem::permissions(entry.path(), std::filesystem::perms::owner_all, ignored);
    std::filesystem::remove_all(dir_, ignored);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Writes `text` into the file `name` of the folder and returns its path.
  std::string writeText(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  static std::string readText(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::filesystem::path dir_;
};

}  // namespace uvtk
