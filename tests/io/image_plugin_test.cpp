// OpenImageIO is loaded on the first image read or write and not before (io/image_plugin.h). Each
// check runs in a fresh process (a death test of the "threadsafe" style re-executes this program
// for the one test), since other tests of this program load the plugin.
#include <gtest/gtest.h>
#include <link.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/error.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

// The first loaded object whose path holds `name`, or "".
std::string loadedObject(const char* name) {
  struct Search {
    const char* name;
    std::string found;
  } search{name, ""};
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        auto* s = static_cast<Search*>(data);
        if (info->dlpi_name && std::strstr(info->dlpi_name, s->name)) s->found = info->dlpi_name;
        return s->found.empty() ? 0 : 1;
      },
      &search);
  return search.found;
}

// Whether the library named `name` is loaded exactly when `expected` says; prints "NAME: PATH" or
// "NAME: not loaded".
bool loadedAsExpected(const char* name, bool expected) {
  const std::string found = loadedObject(name);
  std::fprintf(stderr, "%s: %s\n", name, found.empty() ? "not loaded" : found.c_str());
  return found.empty() == !expected;
}

class ImagePluginTest : public ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    GTEST_FLAG_SET(death_test_style, "threadsafe");
  }
  std::string triangle() const { return writeText("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }
  // Ends a death test's child process, which never reaches TearDown: its own scratch folder (its
  // SetUp made one under its process id) removed first.
  [[noreturn]] void exitChild(int status) {
    ScratchDirTest::TearDown();
    std::exit(status);
  }
};

TEST_F(ImagePluginTest, ReadingAMeshDoesNotLoadOpenImageIo) {
  EXPECT_EXIT(
      {
        EXPECT_EQ(readMesh(triangle()).mesh.faceCount(), 1u);
        exitChild(loadedAsExpected("libOpenImageIO", false) ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "libOpenImageIO: not loaded");
}

// Nor OpenSSL, which only checksums need (io/checksum.h).
TEST_F(ImagePluginTest, ReadingAMeshDoesNotLoadLibcrypto) {
  EXPECT_EXIT(
      {
        readMesh(triangle());
        exitChild(loadedAsExpected("libcrypto", false) ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "libcrypto: not loaded");
}

// The check above can fail: the first image written loads it.
TEST_F(ImagePluginTest, WritingAnImageLoadsOpenImageIo) {
  EXPECT_EXIT(
      {
        readMesh(triangle());
        writeImage(path("a.png"), Image(2, 2, 3, 0.5f), PixelType::UInt8);
        exitChild(loadedAsExpected("libOpenImageIO", true) ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "libOpenImageIO: /.*libOpenImageIO");
}

// A missing plugin fails the image operation in its error class with one line naming the path tried.
TEST_F(ImagePluginTest, AMissingPluginIsOneLineNamingThePath) {
  const auto withoutPlugin = [this](auto operation) {
    ::setenv("UVTK_IMAGE_PLUGIN", "/nonexistent/libuvtk_image_oiio.so", 1);
    try {
      operation();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      exitChild(exitStatus(e));
    }
    exitChild(0);
  };
  const std::string missing =
      ": cannot load the image plugin: /nonexistent/libuvtk_image_oiio.so: cannot open shared object file: No "
      "such file or directory\n";
  const std::string file = writeText("a.png", "any file: the plugin is loaded before it is decoded");
  EXPECT_EXIT(withoutPlugin([&] { readImage(file); }), ::testing::ExitedWithCode(3),
              "/a\\.png: error: cannot read" + missing);
  EXPECT_EXIT(withoutPlugin([&] { writeImage(path("b.png"), Image(2, 2, 3), PixelType::UInt8); }),
              ::testing::ExitedWithCode(4), "/b\\.png: error: cannot write" + missing);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
