// OBJ writing: exact text, per-corner UVs that keep seams, round-trip digits, atomic files.
#include "io/obj_writer.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/io_fixtures.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

std::string toText(const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options = {}) {
  std::ostringstream out;
  writeObj(out, mesh, uvs, options);
  return out.str();
}

TEST(WriteObj, WritesPositionsSharedTexcoordsAndFacesInOrder) {
  const UvMap uvs = uvsOf({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
  ObjWriteOptions options;
  options.header = "made by a test\nsecond line";
  EXPECT_EQ(toText(twoTriangles(), &uvs, options),
            "# made by a test\n# second line\n"
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
            "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
}

TEST(WriteObj, GivesAVertexOneTexcoordPerDistinctUvSoSeamsSurvive) {
  // The vt are numbered vertex by vertex.
  // Vertex 0 has u = 0 in the first face and u = 1 in the second: two vt entries for it.
  const UvMap uvs = uvsOf({{0, 0}, {0.5, 0}, {0.5, 1}, {1, 0}, {0.5, 1}, {0.75, 1}});
  const std::string text = toText(twoTriangles(), &uvs);
  EXPECT_EQ(text.substr(text.find("vt")),
            "vt 0 0\nvt 1 0\nvt 0.5 0\nvt 0.5 1\nvt 0.75 1\n"
            "f 1/1 2/3 3/4\nf 1/2 3/4 4/5\n");
}

TEST(WriteObj, WritesNormalsAndTheThirdComponentWhenAsked) {
  Mesh mesh = twoTriangles();
  mesh.normals = {{0, 0, 1}};
  mesh.cornerNormals = {{0, 0, 0}, {0, 0, -1}};  // the second face lacks one normal: written without
  UvMap uvs = uvsOf({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
  uvs.w = {4, 4, 4, 4, 4, 4};
  ObjWriteOptions options;
  options.writeW = true;
  const std::string text = toText(mesh, &uvs, options);
  EXPECT_NE(text.find("vt 0 0 4\n"), std::string::npos) << text;
  EXPECT_NE(text.find("vn 0 0 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("f 1/1/1 2/2/1 3/3/1\nf 1/1 3/3 4/4\n"), std::string::npos) << text;
  EXPECT_NE(toText(mesh, nullptr).find("f 1//1 2//1 3//1\nf 1 3 4\n"), std::string::npos);
}

TEST(WriteObj, WritesTheShortestTextThatRoundTripsTheValue) {
  Mesh mesh = twoTriangles();
  mesh.positions[0] = Vec3(1.0 / 3.0, -0.1, 1e-300);
  const UvMap uvs = uvsOf({{2.0 / 3.0, 0.1}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}});
  std::istringstream doubles(toText(mesh, &uvs));
  std::string keyword;
  double x, y, z, u, v;
  doubles >> keyword >> x >> y >> z;
  EXPECT_EQ(Vec3(x, y, z), mesh.positions[0]);
  while (doubles >> keyword && keyword != "vt") {}
  doubles >> u >> v;
  EXPECT_EQ(u, 2.0 / 3.0);
  EXPECT_EQ(v, 0.1);

  ObjWriteOptions asFloat;
  asFloat.floatPrecision = true;
  const std::string text = toText(mesh, &uvs, asFloat);
  EXPECT_NE(text.find("vt 0.6666667 0.1\n"), std::string::npos) << text;  // 7 digits round-trip this float
  EXPECT_EQ(std::strtof("0.6666667", nullptr), static_cast<float>(2.0 / 3.0));
}

TEST(WriteObj, ListsFacesWithInvalidCornersInAComment) {
  UvMap uvs = uvsOf({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {0, 0}, {0, 1}});
  uvs.faceFlags[1] = kFaceInvalid;
  uvs.cornerInvalid[4] = 1;
  const std::string text = toText(twoTriangles(), &uvs);
  EXPECT_NE(text.find("# 1 faces have corners without a valid UV (written as vt 0 0); 1-based face numbers: 2\nf "),
            std::string::npos)
      << text;
}

class AtomicOutput : public ScratchDirTest {
 protected:
  std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }
};

TEST_F(AtomicOutput, AFileNotCommittedLeavesNothingBehind) {
  const std::string path = (dir_ / "out.obj").string();
  {
    AtomicFile file(path);
    file.stream() << "partial";
    EXPECT_LE(entries(), 1u);  // the temporary, only where it has a name (no O_TMPFILE)
  }
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicOutput, CommitReplacesTheTargetWholeWithTheUsualPermissions) {
  const std::string path = (dir_ / "out.txt").string();
  std::ofstream(path) << "old";
  writeFileAtomically(path, "new text");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "new text");
  EXPECT_EQ(entries(), 1u);
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  const mode_t mask = ::umask(0);
  ::umask(mask);
  EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask);
}

TEST_F(AtomicOutput, AMissingFolderIsAnOutputErrorNamingThePath) {
  const std::string path = (dir_ / "no" / "such" / "out.obj").string();
  try {
    writeObj(path, twoTriangles(), nullptr);
    FAIL() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": error: cannot write"), std::string::npos) << e.what();
  }
}

TEST_F(AtomicOutput, ATargetThatIsAFolderIsAnOutputErrorAndLeavesNoTemporary) {
  fs::create_directories(dir_ / "taken");
  EXPECT_THROW(writeFileAtomically((dir_ / "taken").string(), "x"), OutputError);
  EXPECT_EQ(entries(), 1u);
  EXPECT_TRUE(fs::is_directory(dir_ / "taken"));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
