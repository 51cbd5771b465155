// The parallel OBJ reader (readObjText, readObjFile): whatever the chunks and threads, exactly the
// mesh, warnings and errors of the sequential reader (readObj on a stream).
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/error.h"
#include "io/io_fixtures.h"
#include "io/mesh_reader.h"
#include "meshes/generators.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using namespace std::string_literals;

// What a read gives: the mesh and warnings, or the error message.
struct Outcome {
  ReadMeshResult result;
  std::string error;
};

template <typename Read>
Outcome outcomeOf(Read read) {
  Outcome o;
  try {
    o.result = read();
  } catch (const InputError& e) {
    o.error = e.what();
  }
  return o;
}

Outcome sequential(const std::string& text) {
  return outcomeOf([&] {
    std::istringstream in(text);
    return readObj(in, "t.obj");
  });
}

Outcome chunked(const std::string& text, std::size_t chunkBytes, int threads) {
  return outcomeOf([&] { return readObjText(text, "t.obj", threads, chunkBytes); });
}

// Every array and every warning equal, bit for bit.
void expectSame(const Outcome& expected, const Outcome& actual) {
  ASSERT_EQ(expected.error, actual.error);
  const Mesh &a = expected.result.mesh, &b = actual.result.mesh;
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.texcoords, b.texcoords);
  EXPECT_EQ(a.cornerTexcoords, b.cornerTexcoords);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.cornerNormals, b.cornerNormals);
  const MeshWarnings &w = expected.result.warnings, &v = actual.result.warnings;
  EXPECT_EQ(w.degenerateFaces, v.degenerateFaces);
  EXPECT_EQ(w.unreferencedVertices, v.unreferencedVertices);
  EXPECT_EQ(w.nonSimplePolygons, v.nonSimplePolygons);
  EXPECT_EQ(w.firstNonSimplePolygonLine, v.firstNonSimplePolygonLine);
  EXPECT_EQ(w.vertexColours, v.vertexColours);
  EXPECT_EQ(w.parameterVertices, v.parameterVertices);
}

// The text read in chunks of every size from 1 byte to past its length (all sizes for short texts,
// a spread of them for long ones), on 1, 2 and 3 threads.
void expectChunkedLikeSequential(const std::string& text) {
  const Outcome expected = sequential(text);
  std::vector<std::size_t> sizes;
  for (std::size_t s = 1; s <= text.size() + 1; s += text.size() < 300 ? 1 : 1 + s / 3) sizes.push_back(s);
  sizes.push_back(kObjChunkBytes);
  for (const std::size_t size : sizes)
    for (const int threads : {1, 2, 3}) {
      SCOPED_TRACE("chunks of " + std::to_string(size) + " bytes on " + std::to_string(threads) + " threads");
      expectSame(expected, chunked(text, size, threads));
      if (::testing::Test::HasFailure()) return;  // one report, not hundreds
    }
}

TEST(ReadObjChunks, AcceptedFormsGiveTheSequentialMesh) {
  for (const std::string& text : std::vector<std::string>{
           kTriangle + "f 1 2 3\n",
           kTriangle + "f 1 2 3",  // no newline at the end
           kTriangle + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 3/1/1 1/2/1 2/3/1\nf 1//1 2//1 3//1\nf 1/1 2/2 3/3\n",
           "v 0 0 0\n" + kTriangle + "vt 0 0\nvt 1 1\nvn 1 0 0\nf -3/-2/-1 -2/-1/-1 -1/-2/-1\n",
           kTriangle + "f -3 -2 -1\n" + kTriangle + "f -3 -2 -1\nf -6 -5 -4\n",
           "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nv 5 5 5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
           "f 1 2 3 4 5\nf 6 1 2\nf 2/1 3/2 4/3 5/4\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf 1 2 3\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 3 2 1\n",
           "# header comment\nmtllib scene.mtl\no Object name\ng group1 group2\ns 1\ns off\nusemtl M.001\n"
           "v 0 0 0 # a comment after data\nv 1 0 0#glued comment\nv 0 1 0\nl 1 2\np 3\n   # indented\nf 1 2 3 # done\n",
           "\r\n\tv\t0 0 0\r\n  v 1\t\t0 0  \r\n\r\n   \t \r\nv 0 1 0\r\n\tf  1\t2 3\t\r\n",
           kTriangle + "vt 0.25\nvt 0.5 0.75\nvt 0.1 0.2 0.3\nf 1/1 2/2 3/3\n",
           "v 0 0 0 1\nv 1 0 0 0.5\nv 0 1 0\nf 1 2 3\n",
           "v 0 0 0 1 0 0\nv 1 0 0 0 1 0.5\nv 0 1 0\nv 0 0 1 255 128 0\nf 1 2 3\nf 1 2 4\n",
           "vp 0.5\nvp 0.5 0.25\n" + kTriangle + "vp 0.1 0.2 1\nf 1 2 3\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf +1/+1/+1 +2/1/+1 3/+1/1\n",
           "v -1.5e+2 .5 5.\nv +2 1E-3 -0\nv 1e-400 -7 00012\nf 1 2 3\n",
           "\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
           "# W\xC3\xBCrfel\no W\xC3\xBCrfel\n" + kTriangle + "f 1 2 3\n",
           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 9 9 9\nv 8 8 8\nf 1 2 3\nf 1 2 2\nf 1 2 4\n",
           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 1 0.5\nf 1 2 3 4\nf 1 3 2 4\nf 1 2 3\nf 1 2 3 5\n",
           "v 2 2 0\nv 1 1 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nvt 0 0\nvt 1 0\nvt 2 0\nvt 3 0\nvt 4 0\n"
           "f 1/1 2/2 3/3 4/4 5/5\n",
           kTriangle + "f 1 2 3\r",  // a carriage return ends the last line
           kTriangle + "f 0001 02 3\n",
       }) {
    SCOPED_TRACE(text);
    expectChunkedLikeSequential(text);
  }
}

TEST(ReadObjChunks, RejectedInputGivesTheSequentialError) {
  for (const std::string& text : std::vector<std::string>{
           "v 0 0 0\nv 0 1.2.3 0\n",
           kTriangle + "vt\n",
           "v 0 0 nan\n",
           "v 1 2 3 1 5\n",
           "v 0 0 0\nv 1 0 0\nf 1 2 7\n",
           kTriangle + "f 0 1 2\n",
           "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n",
           "f 1 2 3\n" + kTriangle,
           kTriangle + "f -1 -2 -4\n",
           kTriangle + "f 1 2 2147483648\n",
           kTriangle + "f 1 2 99999999999999999999999\n",
           kTriangle + "f 1 2 -99999999999999999999999\n",
           kTriangle + "f 1 1x 2\n",
           kTriangle + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n",
           kTriangle + "vt 0 0\nvt 1 0\nf 1/-3 2/2 3/1\n",
           kTriangle + "f 1/1 2/1 3/1\n",
           kTriangle + "vn 0 0 1\nf 1//1 2//2 3//1\n",
           kTriangle + "f 1 2\n",
           kTriangle + "f 1 # 2 3\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf 1/1 2 3\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3//1\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf 1/ 2 3\n",
           kTriangle + "vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n",
           "v 0 0 0\nxyz 1 2\n",
           kTriangle + "f 1 2 \\\n3\n",
           kTriangle,
           "",
           "\n\n# nothing\n",
           "v 0 0 0\nv 1 0\0 0\nf 1 1 1\n"s,
           "v 0 0 0\rv 1 0 0\r",
           "\xFF\xFEv\0 \0"s,
           kTriangle + "\xEF\xBB\xBF" + "f 1 2 3\n",
           "v 0 0 " + std::string(5000, '7') + "x\n",
       }) {
    SCOPED_TRACE(text);
    ASSERT_FALSE(sequential(text).error.empty());
    expectChunkedLikeSequential(text);
  }
}

// An OBJ of every kind of line, from a fixed seed: vertices (some with w or colours), texture
// coordinates of 1 to 3 components, normals, faces of 3 to 6 corners in every form with absolute,
// relative and '+' indices, comments, blank and ignored lines, blanks and tabs, CRLF or LF.
std::string mixedObj(unsigned seed, int lines) {
  std::mt19937 random(seed);
  const auto pick = [&](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
  const auto number = [&] {
    static const char* const kSpellings[] = {"0", "-0", "1", "0.5", "-2.25", "1e-3", "3.", ".75", "+4", "1e-400"};
    return std::string(kSpellings[pick(10)]);
  };
  const std::string newline = seed % 2 ? "\r\n" : "\n";
  std::ostringstream text;
  int v = 0, vt = 0, vn = 0;
  const auto index = [&](int count) {
    const int i = 1 + pick(count);
    switch (pick(4)) {
      case 0: return std::to_string(i - count - 1);  // relative
      case 1: return "+" + std::to_string(i);
      default: return std::to_string(i);
    }
  };
  for (int line = 0; line < lines; ++line) {
    const int kind = v < 4 ? 0 : pick(12);
    const std::string blank = pick(8) == 0 ? "\t " : " ";
    if (kind <= 3) {
      text << "v" << blank << number() << " " << number() << " " << pick(100) * 0.125;
      if (pick(10) == 0)
        text << " 1";
      else if (pick(10) == 0)
        text << " 0.5 0.25 1";
      ++v;
    } else if (kind == 4) {
      text << "vt " << number();
      if (pick(3)) text << " " << number();
      if (pick(3) == 0) text << " " << number();
      ++vt;
    } else if (kind == 5) {
      text << "vn " << number() << " " << number() << " " << number();
      ++vn;
    } else if (kind <= 9) {
      const int form = pick(4);
      if (((form & 1) && vt == 0) || ((form & 2) && vn == 0)) continue;
      const int corners = 3 + (pick(3) == 0 ? pick(4) : 0);
      text << "f";
      for (int c = 0; c < corners; ++c) {
        text << blank << index(v);
        if (form == 1) text << "/" << index(vt);
        if (form == 2) text << "//" << index(vn);
        if (form == 3) text << "/" << index(vt) << "/" << index(vn);
      }
    } else if (kind == 10) {
      static const char* const kOther[] = {"# a comment", "", "   ", "g part", "o thing", "s 1", "usemtl m", "vp 0.5"};
      text << kOther[pick(8)];
    } else {
      text << "f 1 2 3 # " << pick(1000);
    }
    text << newline;
  }
  return text.str();
}

TEST(ReadObjChunks, MixedFilesGiveTheSequentialMeshWhereverTheChunksEnd) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const std::string text = mixedObj(seed, 400);
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_TRUE(sequential(text).error.empty()) << sequential(text).error;
    ASSERT_GT(sequential(text).result.mesh.faceCount(), 100u);
    expectChunkedLikeSequential(text);
  }
}

// The same files with one line broken: the error, at its line, whichever chunk it falls in.
TEST(ReadObjChunks, AnErrorInALaterChunkNamesItsLine) {
  const std::string text = mixedObj(7, 300);
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_GT(lines.size(), 200u);
  for (const std::size_t broken : {lines.size() / 2, lines.size() - 2, lines.size() - 1}) {
    for (const std::string bad : {"f 1 2 x", "v 1 2", "f 1 2 99999", "f -99999 1 2", "q 1", "v 0 0 0 \\"}) {
      std::vector<std::string> copy = lines;
      copy[broken] = bad;
      std::string changed;
      for (const std::string& line : copy) changed += line + "\n";
      SCOPED_TRACE(bad + " on line " + std::to_string(broken + 1));
      const Outcome expected = sequential(changed);
      ASSERT_EQ(expected.error.rfind("t.obj:" + std::to_string(broken + 1) + ": error: ", 0), 0u) << expected.error;
      for (const std::size_t size : {std::size_t{7}, std::size_t{100}, std::size_t{1000}})
        EXPECT_EQ(chunked(changed, size, 2).error, expected.error) << size;
    }
  }
}

TEST(ReadObjChunks, TheFirstErrorInTheFileWinsOverLaterOnes) {
  // Chunks of 64 bytes: line 40 (in a later chunk) refers ahead to a vertex that line 41 defines,
  // and line 60 is malformed; the error of line 40 depends on the 39 vertices before its chunk.
  std::string text;
  for (int i = 0; i < 39; ++i) text += "v " + std::to_string(i) + " 0 0\n";
  text += "f 1 2 40\n";                                                  // line 40
  for (int i = 41; i < 60; ++i) text += "v " + std::to_string(i) + " 1 0\n";  // lines 41-59
  text += "v 1 x 0\n";                                                   // line 60
  const std::string expected = "t.obj:40: error: expected a vertex index in 1..39, found '40'";
  EXPECT_EQ(sequential(text).error, expected);
  for (const std::size_t size : {std::size_t{16}, std::size_t{64}, std::size_t{200}})
    for (const int threads : {1, 2, 4}) EXPECT_EQ(chunked(text, size, threads).error, expected);
  // Without line 40's face, line 60's error, with the line counted through every chunk before it.
  text.replace(text.find("f 1 2 40\n"), 9, "# face\n");
  EXPECT_EQ(chunked(text, 64, 2).error, "t.obj:60: error: expected a number, found 'x'");
}

TEST(ReadObjChunks, RelativeIndicesReachIntoEarlierChunks) {
  std::string text;
  for (int i = 0; i < 100; ++i) text += "v " + std::to_string(i) + " " + std::to_string(i % 7) + " 1\n";
  for (int i = 0; i < 30; ++i) text += "vt 0." + std::to_string(i) + " 1\n";
  text += "f -100/-30 -50/-1 -1/-15\nf 1/1 50/30 100/15 -2/-2\n";
  const Outcome expected = sequential(text);
  ASSERT_TRUE(expected.error.empty()) << expected.error;
  EXPECT_EQ(expected.result.mesh.triangles[0], Triangle({0, 50, 99}));
  EXPECT_EQ(expected.result.mesh.cornerTexcoords[0], Triangle({0, 29, 15}));
  expectChunkedLikeSequential(text);
}

TEST(ReadObjChunks, PolygonsAreTriangulatedWithTheirOwnLinesAcrossChunks) {
  // Non-simple polygons on lines 8 and 10 (a bowtie and a twisted quad): the first one's line is
  // counted through the chunks before it.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 1 0.5\n# a\n\nf 1 3 2 4\nf 1 2 3 4\nf 1 2 3 5\n";
  const Outcome expected = sequential(text);
  EXPECT_EQ(expected.result.warnings.nonSimplePolygons, 2u);
  EXPECT_EQ(expected.result.warnings.firstNonSimplePolygonLine, 8u);
  expectChunkedLikeSequential(text);
}

TEST(ReadObjChunks, AGeneratedMeshWithSeveralThreadsIsTheSequentialOne) {
  // A large sphere as `uvtk_meshgen` writes it (shortest round-trip digits), with normals and UVs.
  const Mesh sphere = meshes::latLongSphere(64, 48);
  std::ostringstream text;
  for (const Vec3& p : sphere.positions) text << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const Vec3& p : sphere.positions) text << "vn " << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) text << "vt " << i * 0.001 << " 0.5\n";
  for (const Triangle& t : sphere.triangles)
    text << "f " << t[0] + 1 << "/" << t[1] + 1 << "/" << t[2] + 1 << " " << t[1] + 1 << "/" << t[2] + 1 << "/"
         << t[0] + 1 << " " << t[2] + 1 << "/" << t[0] + 1 << "/" << t[1] + 1 << "\n";
  const Outcome expected = sequential(text.str());
  ASSERT_TRUE(expected.error.empty()) << expected.error;
  EXPECT_EQ(expected.result.mesh.triangles, sphere.triangles);
  for (const std::size_t size : {std::size_t{100}, std::size_t{4096}, std::size_t{65536}})
    for (const int threads : {1, 2, 3}) expectSame(expected, chunked(text.str(), size, threads));
}

class ReadObjFile : public ScratchDirTest {};

TEST_F(ReadObjFile, AFileReadInChunksIsTheSequentialMesh) {
  for (unsigned seed = 11; seed <= 12; ++seed) {
    const std::string text = mixedObj(seed, 3000);
    const std::string path = writeText("m" + std::to_string(seed) + ".obj", text);
    const Outcome expected = sequential(text);
    ASSERT_TRUE(expected.error.empty()) << expected.error;
    for (const std::size_t size : {std::size_t{1}, std::size_t{13}, std::size_t{1000}, kObjChunkBytes}) {
      SCOPED_TRACE(size);
      const Outcome read = outcomeOf([&] { return readObjFile(path, 2, size); });
      // Messages name the path: compare the mesh here, the errors below.
      expectSame(expected, read);
    }
    expectSame(expected, outcomeOf([&] { return readMesh(path); }));
  }
}

TEST_F(ReadObjFile, ErrorsNameThePathAndTheLineFromAnyChunk) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += "v " + std::to_string(i) + " 0 0\n";
  text += "f 1 2 3\nf 1 2 501\n";  // line 502
  const std::string path = writeText("bad.obj", text);
  for (const std::size_t size : {std::size_t{1}, std::size_t{100}, std::size_t{4096}})
    EXPECT_EQ(outcomeOf([&] { return readObjFile(path, 2, size); }).error,
              path + ":502: error: expected a vertex index in 1..500, found '501'");
  EXPECT_EQ(outcomeOf([&] { return readObjFile(path + "x", 2, 100); }).error,
            path + "x: error: expected a .obj, .off, .ply, .stl, .gltf or .glb extension, found '.objx'");
}

TEST_F(ReadObjFile, AFileOfOneLongLineIsOneChunk) {
  // A 300 000-corner face on one line, and a vertex line padded with blanks, both far longer than a chunk.
  std::string text = "v 0 0 0" + std::string(100000, ' ') + "\n";
  const int n = 300000;
  for (long long i = 1; i < n; ++i) text += "v " + std::to_string(i) + " " + std::to_string(i * i) + " 0\n";
  text += "f";
  for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
  const std::string path = writeText("long.obj", text);
  const Outcome read = outcomeOf([&] { return readObjFile(path, 2, 4096); });
  ASSERT_EQ(read.error, "");
  ASSERT_EQ(read.result.mesh.faceCount(), static_cast<std::size_t>(n - 2));
  EXPECT_EQ(read.result.mesh.triangles.back(), Triangle({0, n - 2, n - 1}));
  expectSame(sequential(text), read);
}

TEST_F(ReadObjFile, AFifoIsReadAsAStream) {
  const std::string path = this->path("pipe.obj");
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(path) << kTriangle << "f 1 2 3\n"; });
  const Outcome read = outcomeOf([&] { return readMesh(path); });
  writer.join();
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.result.mesh.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
