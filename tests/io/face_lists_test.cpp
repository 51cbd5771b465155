// uvtk's lists of faces (invalid, pole, turned away), as each writer notes them and each reader
// gives them back (io/face_lists.h).
#include "io/face_lists.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/mesh_reader.h"
#include "io/obj_writer.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "meshes/generators.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using Faces = std::vector<std::size_t>;

// The faces one line adds to the list `list` (0: invalid, 1: pole, 2: turned away); none when the
// line is not a line of that list (and then no list changes).
Faces lineOf(std::string_view line, bool ply, std::size_t list = 0) {
  ListedFaces lists;
  for (Faces& faces : lists) faces = {99};
  const bool read = readFaceListLine(line, ply, lists);
  for (std::size_t i = 0; i < lists.size(); ++i)
    if (i != list || !read) {
      EXPECT_EQ(lists[i], Faces{99}) << line;
    }
  return read ? Faces(lists[list].begin() + 1, lists[list].end()) : Faces{};
}
Faces objLine(std::string_view line, std::size_t list = 0) { return lineOf(line, false, list); }
Faces plyLine(std::string_view line, std::size_t list = 0) { return lineOf(line, true, list); }

TEST(FaceLists, ReadsTheLinesOfEachFormatsListAndNoOtherComment) {
  EXPECT_EQ(objLine("# 3 faces have corners without a valid UV (written as vt 0 0); 1-based face numbers: 2 7\t10"),
            (Faces{1, 6, 9}));
  EXPECT_EQ(objLine("# more 1-based face numbers: 1 12 "), (Faces{0, 11}));
  EXPECT_EQ(plyLine("comment uvtk: 2 faces have corners without a valid UV (written as s t = 0 0); 0-based face numbers: 0 5"),
            (Faces{0, 5}));
  EXPECT_EQ(plyLine("comment uvtk: more 0-based face numbers: 8"), (Faces{8}));
  EXPECT_EQ(objLine("# 2 faces are pole faces (their corners on the projector's axis fanned); 1-based face numbers: 1 4", 1),
            (Faces{0, 3}));
  EXPECT_EQ(objLine("# more 1-based pole face numbers: 5", 1), (Faces{4}));
  EXPECT_EQ(plyLine("comment uvtk: 1 faces are turned away from the projection (mirrored by design); 0-based face "
                    "numbers: 6",
                    2),
            (Faces{6}));
  EXPECT_EQ(plyLine("comment uvtk: more 0-based turned-away face numbers: 0 3", 2), (Faces{0, 3}));

  // Anything else leaves the faces as they were.
  for (const std::string_view other :
       {"# uvtk map bunny.obj", "# 3 faces have corners", "# more 1-based face numbers: 4 x",
        "# more 1-based face numbers: 0",  // 1-based: 0 is no face
        "# more 1-based face numbers: 4 -5", "# more 1-based face numbers: 4,5",
        "# faces have corners without a valid UV (written as vt 0 0); 1-based face numbers: 2",
        "#3 faces have corners without a valid UV (written as vt 0 0); 1-based face numbers: 2"}) {
    EXPECT_EQ(objLine(other), Faces{}) << other;
  }
  EXPECT_EQ(plyLine("comment more 0-based face numbers: 1"), Faces{});
  EXPECT_EQ(plyLine("# more 1-based face numbers: 1"), Faces{});  // one format's list is not another's
  EXPECT_EQ(objLine("comment uvtk: more 0-based face numbers: 1"), Faces{});
}

TEST(FaceLists, MarksOnlyTheCornersAtZeroOfListedFaces) {
  Mesh mesh;
  mesh.positions.assign(4, Vec3::Zero());
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 2, 3}};
  mesh.texcoords = {Vec3(0, 0, 0), Vec3(0.5, 0, 0), Vec3(0, 0.5, 0), Vec3(0, 0, 7)};  // w plays no part
  mesh.cornerTexcoords = {{0, 1, 2}, {0, 1, 3}, {-1, 1, 2}};
  // Face 0 lists nothing; face 1 twice (counted once); face 2 has no (0, 0) corner; 3 and 9 are beyond the faces.
  std::vector<std::size_t> marked;
  applyFaceLists(mesh, 0, 3, {Faces{1, 2, 1, 3, 9}, Faces{}, Faces{}}, marked);
  EXPECT_EQ(marked, Faces{1});
  EXPECT_EQ(mesh.cornerTexcoords, (std::vector<Triangle>{{0, 1, 2}, {-1, 1, -1}, {-1, 1, 2}}));

  // Numbered from a first face (a glTF mesh's faces after an earlier mesh's), within its count.
  mesh.cornerTexcoords = {{0, 1, 2}, {0, 1, 3}, {0, 0, 0}};
  marked.clear();
  applyFaceLists(mesh, 1, 1, {Faces{0, 1}, Faces{}, Faces{}}, marked);
  EXPECT_EQ(marked, Faces{1});
  EXPECT_EQ(mesh.cornerTexcoords, (std::vector<Triangle>{{0, 1, 2}, {-1, 1, -1}, {0, 0, 0}}));
  EXPECT_TRUE(mesh.listedFaceFlags.empty());

  // Pole and turned-away faces become bits of listedFaceFlags, within the count from the first face.
  applyFaceLists(mesh, 1, 2, {Faces{}, Faces{0, 5}, Faces{1, 0}}, marked);
  EXPECT_EQ(mesh.listedFaceFlags, (std::vector<std::uint8_t>{0, kFacePole | kFaceTurnedAway, kFaceTurnedAway}));

  Mesh without = mesh;
  without.cornerTexcoords.clear();
  marked.clear();
  applyFaceLists(without, 0, 3, {Faces{0, 1, 2}, Faces{}, Faces{}}, marked);
  EXPECT_TRUE(marked.empty());
}

// A mesh like a scan, every third face with one corner without a valid UV, the valid UVs away from (0, 0).
struct Listed {
  Mesh mesh = meshes::scannedPatch(6);
  UvMap uvs;
  std::size_t invalidFaces = 0;
  Listed() {
    const std::size_t faces = mesh.triangles.size();
    uvs.faceFlags.assign(faces, kFaceOk);
    uvs.cornerInvalid.assign(3 * faces, kCornerValid);
    uvs.uv.resize(3 * faces);
    for (std::size_t c = 0; c < 3 * faces; ++c) {
      const Vec3& p = mesh.positions[static_cast<std::size_t>(mesh.triangles[c / 3][c % 3])];
      uvs.uv[c] = Vec2(0.25 + 0.01 * std::abs(p.x()), 0.25 + 0.01 * std::abs(p.y()));
    }
    for (std::size_t f = 1; f < faces; f += 3) {
      uvs.faceFlags[f] = kFaceInvalid;
      uvs.cornerInvalid[3 * f + f % 3] = kCornerMiss;
      ++invalidFaces;
    }
    for (std::size_t f = 0; f < faces; f += 5) uvs.faceFlags[f] |= kFacePole;
    for (std::size_t f = 2; f < faces; f += 2) uvs.faceFlags[f] |= kFaceTurnedAway;
    for (std::size_t f = 0; f < faces; f += 4) uvs.faceFlags[f] |= kFaceSeamStraddle;  // not listed
  }
  // Every corner read back without a UV is one written without a valid UV, and the other way round.
  void expectSameInvalidCorners(const ReadMeshResult& read, const std::string& format) const {
    ASSERT_EQ(read.mesh.cornerTexcoords.size(), mesh.triangles.size()) << format;
    EXPECT_EQ(read.warnings.listedInvalidUvFaces, invalidFaces) << format;
    EXPECT_EQ(read.listedInvalidUvFaces.size(), invalidFaces) << format;
    std::size_t differing = 0;
    for (std::size_t c = 0; c < uvs.cornerInvalid.size(); ++c)
      differing += (read.mesh.cornerTexcoords[c / 3][c % 3] < 0) != (uvs.cornerInvalid[c] != kCornerValid) ? 1 : 0;
    EXPECT_EQ(differing, 0u) << format;
    // The pole and turned-away faces come back as such, and no other flag.
    ASSERT_EQ(read.mesh.listedFaceFlags.size(), mesh.triangles.size()) << format;
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      ASSERT_EQ(read.mesh.listedFaceFlags[f], uvs.faceFlags[f] & (kFacePole | kFaceTurnedAway)) << format << " face " << f;
  }
};

TEST(FaceLists, EveryWritersListsComeBackAsTheSameCornersWithoutAUvAndTheSameFaceFlags) {
  const Listed listed;
  ASSERT_GT(listed.invalidFaces, kFacesPerLine);  // lists of several lines in every format

  std::ostringstream obj;
  writeObj(obj, listed.mesh, &listed.uvs);
  const std::string text = obj.str();
  std::size_t listLines = 0, longest = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.find("face numbers:") != std::string::npos) ++listLines, longest = std::max(longest, line.size());
  EXPECT_GT(listLines, 1u);
  EXPECT_LT(longest, 16 * kFacesPerLine);  // no line near the reader's 64 MiB limit
  // In parallel chunks of several sizes (a chunk may begin inside the list) and as a stream.
  for (const std::size_t chunkBytes : {std::size_t{4096}, std::size_t{100000}, kObjChunkBytes})
    listed.expectSameInvalidCorners(readObjText(text, "listed.obj", 2, chunkBytes), "obj " + std::to_string(chunkBytes));
  std::istringstream objStream(text);
  listed.expectSameInvalidCorners(readObj(objStream, "listed.obj"), "obj stream");

  for (const bool ascii : {false, true}) {
    PlyWriteOptions options;
    options.ascii = ascii;
    std::stringstream ply;
    writePly(ply, listed.mesh, &listed.uvs, options);
    listed.expectSameInvalidCorners(readPly(ply, "listed.ply"), ascii ? "ascii ply" : "binary ply");
  }

  std::stringstream glb;
  writeGlb(glb, listed.mesh, &listed.uvs);
  listed.expectSameInvalidCorners(readGltf(glb.str(), "listed.glb", ".", true), "glb");
}

TEST(FaceLists, AFileWithoutTheListKeepsItsCornersAtZero) {
  const Listed listed;
  std::ostringstream obj;
  writeObj(obj, listed.mesh, &listed.uvs);
  // The same file without the list's lines: its invalid corners are the (0, 0) they hold.
  std::istringstream lines(obj.str());
  std::string text;
  for (std::string line; std::getline(lines, line);)
    if (line.find("face numbers:") == std::string::npos) text += line + "\n";
  const ReadMeshResult read = readObjText(text, "unlisted.obj", 2, 4096);
  EXPECT_EQ(read.warnings.listedInvalidUvFaces, 0u);
  for (const Triangle& t : read.mesh.cornerTexcoords) ASSERT_EQ(std::count(t.begin(), t.end(), -1), 0);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
