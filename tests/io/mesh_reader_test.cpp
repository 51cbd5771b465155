// The strict OBJ and OFF readers: every accepted form, and every rejected one with its exact message.
#include "io/mesh_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <clocale>
#include <filesystem>
#include <fstream>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/io_fixtures.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;
using namespace std::string_literals;

const Triangle kNone = {-1, -1, -1};

ReadMeshResult obj(const std::string& text) {
  std::istringstream in(text);
  return readObj(in, "t.obj");
}

ReadMeshResult off(const std::string& text) {
  std::istringstream in(text);
  return readOff(in, "t.off");
}

// The message of the InputError that reading `text` throws; a failure if it throws none.
template <typename Read>
std::string errorOf(Read read, const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

std::string objError(const std::string& text) { return errorOf(obj, text); }
std::string offError(const std::string& text) { return errorOf(off, text); }

const std::string kOffTriangleHeader = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";  // header, counts, vertices: lines 1-5

// ---------------------------------------------------------------------------------------------
// OBJ, accepted forms

TEST(ReadObj, ReadsVerticesAndAPlainFace) {
  const Mesh m = obj("v 0 0 0\nv 1 0 0\nv 0 1.5 -2e-3\nf 1 2 3\n").mesh;
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[2], Vec3(0, 1.5, -2e-3));
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
  EXPECT_FALSE(m.hasTexcoords());
  EXPECT_FALSE(m.hasNormals());
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_TRUE(m.normals.empty());
}

TEST(ReadObj, FaceFormVertexSlashTexcoord) {
  const Mesh m = obj(kTriangle + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/3 2/2 3/1\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({{2, 1, 0}}));
  EXPECT_FALSE(m.hasNormals());
  EXPECT_EQ(m.texcoords[2], Vec3(0, 1, 0));
}

TEST(ReadObj, FaceFormVertexDoubleSlashNormal) {
  const Mesh m = obj(kTriangle + "vn 0 0 1\nvn 0 0 -1\nf 1//2 2//1 3//2\n").mesh;
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{1, 0, 1}}));
  EXPECT_FALSE(m.hasTexcoords());
  EXPECT_EQ(m.normals[1], Vec3(0, 0, -1));
}

TEST(ReadObj, FaceFormVertexTexcoordNormal) {
  const Mesh m = obj(kTriangle + "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 3/1/1 1/2/1 2/3/1\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{2, 0, 1}}));
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({{0, 1, 2}}));
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{0, 0, 0}}));
}

TEST(ReadObj, NegativeIndicesCountBackFromTheLastVertex) {
  const Mesh m = obj("v 0 0 0\n" + kTriangle + "vt 0 0\nvt 1 1\nvn 1 0 0\nf -3/-2/-1 -2/-1/-1 -1/-2/-1\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{1, 2, 3}}));
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({{0, 1, 0}}));
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{0, 0, 0}}));
}

TEST(ReadObj, NegativeIndicesCountFromTheVerticesDefinedBeforeTheFace) {
  const Mesh m = obj(kTriangle + "f -3 -2 -1\n" + kTriangle + "f -3 -2 -1\nf -6 -5 -4\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}, {3, 4, 5}, {0, 1, 2}}));
}

TEST(ReadObj, PolygonsAreFanTriangulatedInPlace) {
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nv 5 5 5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
  const Mesh m = obj(vertices + "f 1 2 3 4 5\nf 6 1 2\nf 2/1 3/2 4/3 5/4\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {5, 0, 1}, {1, 2, 3}, {1, 3, 4}}));
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({kNone, kNone, kNone, kNone, {0, 1, 2}, {0, 2, 3}}));
}

TEST(ReadObj, CornerTablesHoldMinusOneForFacesWithoutTheAttribute) {
  const Mesh m = obj(kTriangle + "vt 0 0\nvn 0 0 1\nf 1 2 3\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 3 2 1\n").mesh;
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({kNone, {0, 0, 0}, kNone, kNone}));
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({kNone, kNone, {0, 0, 0}, kNone}));
}

TEST(ReadObj, CornerTablesStayEmptyWhenTheFileHasAttributesButNoFaceUsesThem) {
  const Mesh m = obj(kTriangle + "vt 0 0\nvn 0 0 1\nf 1 2 3\n").mesh;
  EXPECT_EQ(m.texcoords.size(), 1u);
  EXPECT_EQ(m.normals.size(), 1u);
  EXPECT_TRUE(m.cornerTexcoords.empty());
  EXPECT_TRUE(m.cornerNormals.empty());
}

TEST(ReadObj, AcceptsCommentsGroupsMaterialsSmoothingLinesAndPoints) {
  const Mesh m = obj("# header comment\n"
                     "mtllib scene.mtl\n"
                     "o Object name with spaces\n"
                     "g group1 group2\n"
                     "s 1\n"
                     "s off\n"
                     "usemtl Material.001\n"
                     "v 0 0 0 # a comment after data\n"
                     "v 1 0 0#glued comment\n"
                     "v 0 1 0\n"
                     "l 1 2\n"
                     "p 3\n"
                     "   # indented comment\n"
                     "f 1 2 3 # done\n")
                     .mesh;
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadObj, AcceptsCrlfLineEndingsTabsAndBlankLines) {
  const Mesh m = obj("\r\n\tv\t0 0 0\r\n  v 1\t\t0 0  \r\n\r\n   \t \r\nv 0 1 0\r\n\tf  1\t2 3\t\r\n").mesh;
  EXPECT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadObj, AcceptsALastLineWithoutNewline) {
  EXPECT_EQ(obj(kTriangle + "f 1 2 3").mesh.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadObj, TexcoordsWithOneTwoOrThreeComponentsFillMissingOnesWithZero) {
  const Mesh m = obj(kTriangle + "vt 0.25\nvt 0.5 0.75\nvt 0.1 0.2 0.3\nf 1/1 2/2 3/3\n").mesh;
  ASSERT_EQ(m.texcoords.size(), 3u);
  EXPECT_EQ(m.texcoords[0], Vec3(0.25, 0, 0));
  EXPECT_EQ(m.texcoords[1], Vec3(0.5, 0.75, 0));
  EXPECT_EQ(m.texcoords[2], Vec3(0.1, 0.2, 0.3));
}

TEST(ReadObj, AcceptsAndIgnoresAVertexWeight) {
  const ReadMeshResult r = obj("v 0 0 0 1\nv 1 0 0 0.5\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(r.mesh.positions[1], Vec3(1, 0, 0));  // not divided by w
  EXPECT_EQ(r.warnings.vertexColours, 0u);
}

TEST(ReadObj, AcceptsVertexColoursDropsAndCountsThem) {
  const ReadMeshResult r = obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0.5\nv 0 1 0\nv 0 0 1 255 128 0\nf 1 2 3\nf 1 2 4\n");
  ASSERT_EQ(r.mesh.positions.size(), 4u);
  EXPECT_EQ(r.mesh.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(r.mesh.positions[3], Vec3(0, 0, 1));
  EXPECT_EQ(r.warnings.vertexColours, 3u);
}

TEST(ReadObj, IgnoresAndCountsParameterSpaceVertices) {
  const ReadMeshResult r = obj("vp 0.5\nvp 0.5 0.25\n" + kTriangle + "vp 0.1 0.2 1\nf 1 2 3\n");
  EXPECT_EQ(r.mesh.positions.size(), 3u);
  EXPECT_EQ(r.mesh.faceCount(), 1u);
  EXPECT_EQ(r.warnings.parameterVertices, 3u);
  EXPECT_EQ(objError("vp\n"), "t.obj:1: error: expected a u parameter, found end of line");
  EXPECT_EQ(objError("vp 1 2 3 4\n"), "t.obj:1: error: expected end of line, found '4'");
  EXPECT_EQ(objError("vp 1 x\n"), "t.obj:1: error: expected a number, found 'x'");
}

TEST(ReadObj, AcceptsAPlusSignOnIndicesAsOnNumbers) {
  const Mesh m = obj(kTriangle + "vt 0 0\nvn 0 0 1\nf +1/+1/+1 +2/1/+1 3/+1/1\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
  EXPECT_EQ(m.cornerTexcoords, std::vector<Triangle>({{0, 0, 0}}));
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{0, 0, 0}}));
  EXPECT_EQ(off(kOffTriangleHeader + "+3 0 +1 2\n").mesh.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadObj, NumbersInEveryDecimalSpelling) {
  const Mesh m = obj("v -1.5e+2 .5 5.\nv +2 1E-3 -0\nv 1e-400 -7 00012\nf 1 2 3\n").mesh;
  EXPECT_EQ(m.positions[0], Vec3(-150, 0.5, 5));
  EXPECT_EQ(m.positions[1], Vec3(2, 0.001, 0));
  EXPECT_EQ(m.positions[2], Vec3(0, -7, 12));  // 1e-400 underflows to 0: finite, so accepted
}

TEST(ReadObj, SkipsAUtf8ByteOrderMark) {
  const Mesh m = obj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").mesh;
  EXPECT_EQ(m.positions[0], Vec3(0, 0, 0));
  EXPECT_EQ(m.faceCount(), 1u);
}

TEST(ReadObj, AcceptsUtf8TextInNamesAndComments) {
  EXPECT_EQ(obj("# Würfel\no Würfel\n" + kTriangle + "f 1 2 3\n").mesh.faceCount(), 1u);
}

// A comma locale for C++ streams and, where installed, for the C library: the reader must not care.
struct CommaDecimalPoint : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
};

TEST(ReadObj, IgnoresTheGlobalLocale) {
  const std::locale previous = std::locale::global(std::locale(std::locale::classic(), new CommaDecimalPoint));
  const std::string previousC = std::setlocale(LC_NUMERIC, nullptr);
  std::setlocale(LC_NUMERIC, "de_DE.UTF-8");  // may be missing; then the C++ locale alone is tested
  std::string commaError;
  Mesh m;
  try {
    m = obj("v 0.5 1.25 -2.5\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").mesh;
    commaError = objError("v 0,5 0 0\n");
  } catch (...) {
    std::locale::global(previous);
    std::setlocale(LC_NUMERIC, previousC.c_str());
    throw;
  }
  std::locale::global(previous);
  std::setlocale(LC_NUMERIC, previousC.c_str());
  EXPECT_EQ(m.positions[0], Vec3(0.5, 1.25, -2.5));
  EXPECT_EQ(commaError, "t.obj:1: error: expected a number, found '0,5'");
}

TEST(ReadObj, HandlesVeryLongLines) {
  // A convex 100 000-gon (corners on a parabola) on one line, and a megabyte of blanks inside a vertex line.
  std::string text = "v 0 0 0" + std::string(1 << 20, ' ') + "\n";
  const int n = 100000;
  for (long long i = 1; i < n; ++i) text += "v " + std::to_string(i) + " " + std::to_string(i * i) + " 0\n";
  text += "f";
  for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
  text += "\n";
  const Mesh m = obj(text).mesh;
  ASSERT_EQ(m.faceCount(), static_cast<std::size_t>(n - 2));
  EXPECT_EQ(m.triangles.back(), Triangle({0, n - 2, n - 1}));
}

// ---------------------------------------------------------------------------------------------
// OBJ, rejected input

TEST(ReadObj, RejectsMalformedNumbers) {
  for (const std::string bad :
       {"abc", "1.2.3", "1e", "1.0x", "0x10", "--1", "+-1", "1,5", "e5", ".", "-", "+", "1..2"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(objError("v 0 0 0\nv 0 " + bad + " 0\n"), "t.obj:2: error: expected a number, found '" + bad + "'");
  }
  EXPECT_EQ(objError(kTriangle + "vt 0 1.0x\n"), "t.obj:4: error: expected a number, found '1.0x'");
  EXPECT_EQ(objError(kTriangle + "vn 0 0 1e\n"), "t.obj:4: error: expected a number, found '1e'");
}

TEST(ReadObj, RejectsAMissingNumberAsEndOfLine) {
  EXPECT_EQ(objError("v\n"), "t.obj:1: error: expected an x coordinate, found end of line");
  EXPECT_EQ(objError(kTriangle + "vt\n"), "t.obj:4: error: expected a u coordinate, found end of line");
  EXPECT_EQ(objError(kTriangle + "vt # only a comment\n"),
            "t.obj:4: error: expected a u coordinate, found end of line");
}

TEST(ReadObj, RejectsNonFiniteValues) {
  for (const std::string bad : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e999", "-1e400", "+inf"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(objError("v 0 0 " + bad + "\n"), "t.obj:1: error: expected a finite number, found '" + bad + "'");
    EXPECT_EQ(objError("v 0 0 0\nvt " + bad + " 0\n"), "t.obj:2: error: expected a finite number, found '" + bad + "'");
    EXPECT_EQ(objError("\nvn 0 " + bad + " 1\n"), "t.obj:2: error: expected a finite number, found '" + bad + "'");
  }
  EXPECT_EQ(objError("v 0 0 0 nan\n"), "t.obj:1: error: expected a finite number, found 'nan'");  // w too
}

TEST(ReadObj, RejectsTooFewCoordinates) {
  EXPECT_EQ(objError("v 0 0 0\nv 1 2\n"), "t.obj:2: error: expected a z coordinate, found end of line");
  EXPECT_EQ(objError("v 1\n"), "t.obj:1: error: expected a y coordinate, found end of line");
  EXPECT_EQ(objError("vn 0 1\n"), "t.obj:1: error: expected a normal's z component, found end of line");
}

TEST(ReadObj, RejectsTooManyCoordinates) {
  EXPECT_EQ(objError("v 1 2 3 1 5\n"), "t.obj:1: error: expected x y z, x y z w or x y z r g b, found 5 numbers");
  EXPECT_EQ(objError("v 1 2 3 1 5 6 7\n"),
            "t.obj:1: error: expected x y z, x y z w or x y z r g b, found 7 numbers");
  EXPECT_EQ(objError("v 1 2 3 0.5 0.5 x\n"), "t.obj:1: error: expected a number, found 'x'");
  EXPECT_EQ(objError("vn 0 0 1 7\n"), "t.obj:1: error: expected end of line, found '7'");
  EXPECT_EQ(objError("vt 0 0 0 8\n"), "t.obj:1: error: expected end of line, found '8'");
}

TEST(ReadObj, RejectsAVertexIndexPastTheEnd) {
  EXPECT_EQ(objError("v 0 0 0\nv 1 0 0\nf 1 2 7\n"), "t.obj:3: error: expected a vertex index in 1..2, found '7'");
}

TEST(ReadObj, RejectsVertexIndexZero) {
  EXPECT_EQ(objError(kTriangle + "f 0 1 2\n"), "t.obj:4: error: expected a vertex index in 1..3, found '0'");
}

TEST(ReadObj, ResolvesIndicesAgainstTheVerticesDefinedSoFar) {
  EXPECT_EQ(objError("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n"),
            "t.obj:3: error: expected a vertex index in 1..2, found '3'");
  EXPECT_EQ(objError("f 1 2 3\n" + kTriangle),
            "t.obj:1: error: expected a vertex index (none is defined before this line), found '1'");
}

TEST(ReadObj, RejectsANegativeIndexBeforeTheFirstVertex) {
  EXPECT_EQ(objError(kTriangle + "f -1 -2 -4\n"), "t.obj:4: error: expected a vertex index in -3..-1, found '-4'");
}

TEST(ReadObj, RejectsNonIntegerIndices) {
  for (const std::string bad : {"1.5", "x", "1e0", "+-1", "++1", "+", "+0", "1x", "--1", "0x1"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(objError(kTriangle + "f 1 " + bad + " 3\n"),
              "t.obj:4: error: expected a vertex index in 1..3, found '" + bad + "'");
  }
}

TEST(ReadObj, RejectsIndicesOverflowingInt) {
  EXPECT_EQ(objError(kTriangle + "f 1 2 2147483648\n"),
            "t.obj:4: error: expected a vertex index in 1..3, found '2147483648'");
  EXPECT_EQ(objError(kTriangle + "f 1 2 99999999999999999999999\n"),
            "t.obj:4: error: expected a vertex index in 1..3, found '99999999999999999999999'");
  EXPECT_EQ(objError(kTriangle + "f 1 2 -99999999999999999999999\n"),
            "t.obj:4: error: expected a vertex index in -3..-1, found '-99999999999999999999999'");
}

TEST(ReadObj, RejectsTexcoordIndicesOutOfRange) {
  const std::string head = kTriangle + "vt 0 0\nvt 1 0\n";  // lines 1-5
  EXPECT_EQ(objError(head + "f 1/1 2/2 3/3\n"),
            "t.obj:6: error: expected a texture coordinate index in 1..2, found '3'");
  EXPECT_EQ(objError(head + "f 1/0 2/2 3/1\n"),
            "t.obj:6: error: expected a texture coordinate index in 1..2, found '0'");
  EXPECT_EQ(objError(head + "f 1/-3 2/2 3/1\n"),
            "t.obj:6: error: expected a texture coordinate index in -2..-1, found '-3'");
  EXPECT_EQ(objError(kTriangle + "f 1/1 2/1 3/1\n"),
            "t.obj:4: error: expected a texture coordinate index (none is defined before this line), found '1'");
}

TEST(ReadObj, RejectsNormalIndicesOutOfRange) {
  const std::string head = kTriangle + "vn 0 0 1\n";  // lines 1-4
  EXPECT_EQ(objError(head + "f 1//1 2//2 3//1\n"), "t.obj:5: error: expected a normal index in 1..1, found '2'");
  EXPECT_EQ(objError(head + "vt 0 0\nf 1/1/1 2/1/1 3/1/1.5\n"),
            "t.obj:6: error: expected a normal index in 1..1, found '1.5'");
  EXPECT_EQ(objError(head + "f 1//-2 2//1 3//1\n"), "t.obj:5: error: expected a normal index in -1..-1, found '-2'");
}

TEST(ReadObj, RejectsFacesWithFewerThanThreeVertices) {
  EXPECT_EQ(objError(kTriangle + "f 1 2\n"), "t.obj:4: error: expected at least 3 vertices in a face, found 2");
  EXPECT_EQ(objError(kTriangle + "f\n"), "t.obj:4: error: expected at least 3 vertices in a face, found 0");
  EXPECT_EQ(objError(kTriangle + "f 1 # 2 3\n"), "t.obj:4: error: expected at least 3 vertices in a face, found 1");
}

TEST(ReadObj, RejectsMixedIndexFormsWithinAFace) {
  const std::string head = kTriangle + "vt 0 0\nvn 0 0 1\n";  // lines 1-5
  EXPECT_EQ(objError(head + "f 1/1 2 3\n"),
            "t.obj:6: error: expected a corner of the same form as the first (v/vt), found '2'");
  EXPECT_EQ(objError(head + "f 1 2 3//1\n"),
            "t.obj:6: error: expected a corner of the same form as the first (v), found '3//1'");
  EXPECT_EQ(objError(head + "f 1/1/1 2/1/1 3//1\n"),
            "t.obj:6: error: expected a corner of the same form as the first (v/vt/vn), found '3//1'");
}

TEST(ReadObj, RejectsMalformedCorners) {
  for (const std::string bad : {"1/", "1//", "/1", "1/1/", "1/1/1/1", "//1", "1///1", "/"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(objError(kTriangle + "vt 0 0\nvn 0 0 1\nf " + bad + " 2 3\n"),
              "t.obj:6: error: expected a face corner v, v/vt, v//vn or v/vt/vn, found '" + bad + "'");
  }
}

TEST(ReadObj, RejectsUnknownKeywords) {
  EXPECT_EQ(objError("v 0 0 0\nxyz 1 2\n"), "t.obj:2: error: expected a keyword (v, vt, vn, f, ...), found 'xyz'");
  EXPECT_EQ(objError("vpx 0.5\n"), "t.obj:1: error: expected a keyword (v, vt, vn, f, ...), found 'vpx'");
  EXPECT_EQ(objError("V 0 0 0\n"), "t.obj:1: error: expected a keyword (v, vt, vn, f, ...), found 'V'");
  EXPECT_EQ(objError("v1 0 0\n"), "t.obj:1: error: expected a keyword (v, vt, vn, f, ...), found 'v1'");
}

TEST(ReadObj, RejectsLineContinuations) {
  EXPECT_EQ(objError(kTriangle + "f 1 2 \\\n3\n"),
            "t.obj:4: error: expected end of line, found a '\\' line continuation");
  EXPECT_EQ(objError("v 0 0 \\ # comment\n0\n"),
            "t.obj:1: error: expected end of line, found a '\\' line continuation");
}

TEST(ReadObj, RejectsAFileWithoutFaces) {
  EXPECT_EQ(objError(kTriangle), "t.obj:4: error: expected at least one face, found end of file");
  EXPECT_EQ(objError(kTriangle + "l 1 2\np 3\n# end"), "t.obj:7: error: expected at least one face, found end of file");
}

TEST(ReadObj, RejectsAnEmptyFile) {
  EXPECT_EQ(objError(""), "t.obj:1: error: expected at least one face, found end of file");
  EXPECT_EQ(objError("\n\n# nothing\n"), "t.obj:4: error: expected at least one face, found end of file");
}

TEST(ReadObj, RejectsNulAndControlBytes) {
  EXPECT_EQ(objError("v 0 0 0\nv 1 0\0 0\n"s), "t.obj:2: error: expected text, found byte 0x00");
  EXPECT_EQ(objError("# comment \x1B[31m\n"), "t.obj:1: error: expected text, found byte 0x1B");
  EXPECT_EQ(objError("v 0 0 0\x7F\n"), "t.obj:1: error: expected text, found byte 0x7F");
  // A carriage return is a line ending only right before the line feed (old Mac files are rejected).
  EXPECT_EQ(objError("v 0 0 0\rv 1 0 0\r"), "t.obj:1: error: expected text, found byte 0x0D");
  EXPECT_EQ(objError("\x01\x02\x03"), "t.obj:1: error: expected text, found byte 0x01");
}

TEST(ReadObj, RejectsUtf16) {
  EXPECT_EQ(objError("\xFF\xFEv\0 \0"s), "t.obj:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark");
  EXPECT_EQ(objError("\xFE\xFF\0v\0 "s), "t.obj:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark");
  EXPECT_EQ(objError("v\0 \0"s), "t.obj:1: error: expected text, found byte 0x00");  // UTF-16 without a mark
}

TEST(ReadObj, ABomIsOnlySkippedAtTheStartOfTheFile) {
  const std::string bom = "\xEF\xBB\xBF";
  EXPECT_EQ(objError(kTriangle + bom + "f 1 2 3\n"),
            "t.obj:4: error: expected a keyword (v, vt, vn, f, ...), found '" + bom + "f'");
}

TEST(ReadObj, RefusesALineLongerThan64MiB) {
  // 64 MiB of blanks inside a vertex line on line 2: refused as soon as the limit is passed.
  const std::string text = "v 0 0 0\nv 1 1 1" + std::string(std::size_t{64} << 20, ' ') + "\nf 1 1 1\n";
  EXPECT_EQ(objError(text), "t.obj:2: error: expected a line of at most 64 MiB, found a longer one");
}

TEST(ReadObj, LinesSpanningReadBlocksAreWhole) {
  // The reader's blocks (64 KiB doubling to 1 MiB) are powers of two, so 9-byte vertex lines cross
  // their boundaries at every offset.
  std::string text;
  const int n = (3 << 20) / 9;
  for (int i = 0; i < n; ++i) text += "v 1 2 30\n";
  text += "f 1 2 3\nf -1 -2 -3";  // the last line without a newline
  const Mesh m = obj(text).mesh;
  ASSERT_EQ(m.positions.size(), std::size_t(n));
  for (const Vec3& p : m.positions) ASSERT_EQ(p, Vec3(1, 2, 30));
  EXPECT_EQ(m.triangles.back(), Triangle({n - 1, n - 2, n - 3}));
}

TEST(ReadObj, QuotesAtMostFortyCharactersOfALongToken) {
  EXPECT_EQ(objError("v 0 0 " + std::string(5000, '7') + "x\n"),
            "t.obj:1: error: expected a number, found '" + std::string(40, '7') + "...'");
}

// A stream whose reading fails, as a disk or a network file system can.
struct FailingBuffer : std::streambuf {
  int_type underflow() override { throw std::runtime_error("device error"); }
};

TEST(ReadObj, ReportsAStreamThatFailsWhileReading) {
  FailingBuffer buffer;
  std::istream in(&buffer);
  try {
    readObj(in, "t.obj");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "t.obj: error: cannot read: input/output error");
  }
}

// ---------------------------------------------------------------------------------------------
// OFF, accepted forms

TEST(ReadOff, ReadsVerticesAndFacesWithZeroBasedIndices) {
  const Mesh m = off("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 -0.5e1\n3 0 1 2\n3 0 2 3\n").mesh;
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[3], Vec3(0, 1, -5));
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}, {0, 2, 3}}));
  EXPECT_FALSE(m.hasNormals());
  EXPECT_FALSE(m.hasTexcoords());
}

TEST(ReadOff, PolygonsAreFanTriangulatedInPlace) {
  const Mesh m = off("OFF\n5 3 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 4 0 1 2 3\n3 0 1 2\n4 1 2 3 4\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{4, 0, 1}, {4, 1, 2}, {4, 2, 3}, {0, 1, 2}, {1, 2, 3}, {1, 3, 4}}));
}

TEST(ReadOff, AcceptsCountsOnTheHeaderLine) {
  const Mesh m = off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadOff, AcceptsCommentsBlankLinesCrlfAndTabsAnywhere) {
  const Mesh m =
      off("# made by hand\r\n\r\nOFF # header\r\n# counts next\r\n\t3 1\t0\r\n\r\n0 0 0 # first\r\n"
          "# between vertices\r\n1 0 0\r\n\t0\t1\t0\r\n\r\n3 0 1 2 # face\r\n\r\n# trailing comment\r\n  \r\n")
          .mesh;
  EXPECT_EQ(m.positions[2], Vec3(0, 1, 0));
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}}));
}

TEST(ReadOff, NoffNormalsAreUsedByEveryCornerOfTheirVertex) {
  const Mesh m = off("NOFF\n4 2 0\n0 0 0 0 0 1\n1 0 0 0 1 0\n1 1 0 1 0 0\n0 1 0 0 0 -1\n3 0 1 2\n4 0 1 2 3\n").mesh;
  ASSERT_EQ(m.normals.size(), 4u);
  EXPECT_EQ(m.normals[1], Vec3(0, 1, 0));
  EXPECT_EQ(m.normals[3], Vec3(0, 0, -1));
  EXPECT_EQ(m.cornerNormals, m.triangles);
  EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{0, 1, 2}, {0, 1, 2}, {0, 2, 3}}));
}

TEST(ReadOff, CoffColoursAreReadAndDropped) {
  const Mesh m = off("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0\n0 1 0 0.1 0.2 0.3 1.0\n3 0 1 2\n").mesh;
  EXPECT_EQ(m.positions[1], Vec3(1, 0, 0));
  EXPECT_EQ(m.positions[2], Vec3(0, 1, 0));
  EXPECT_FALSE(m.hasNormals());
}

TEST(ReadOff, CnoffAndNcoffCarryNormalsThenColours) {
  for (const std::string header : {"CNOFF", "NCOFF"}) {
    SCOPED_TRACE(header);
    const Mesh m = off(header + "\n3 1 0\n0 0 0 0 0 1 1 0 0\n1 0 0 0 0 1 0 1 0 1\n0 1 0 0 1 0 0 0 1\n3 0 1 2\n").mesh;
    EXPECT_EQ(m.normals[2], Vec3(0, 1, 0));
    EXPECT_EQ(m.cornerNormals, std::vector<Triangle>({{0, 1, 2}}));
  }
}

TEST(ReadOff, AcceptsAndIgnoresFaceColours) {
  const Mesh m = off(kOffTriangleHeader.substr(0, 4) + "3 4 0\n0 0 0\n1 0 0\n0 1 0\n" +
                     "3 0 1 2 255 0 0\n3 0 1 2 0.5 0.5 0.5 1\n3 0 1 2 7\n3 2 1 0 1 1 1 0.25\n")
                     .mesh;
  EXPECT_EQ(m.triangles, std::vector<Triangle>({{0, 1, 2}, {0, 1, 2}, {0, 1, 2}, {2, 1, 0}}));
}

// ---------------------------------------------------------------------------------------------
// OFF, rejected input

TEST(ReadOff, RejectsAMissingOrWrongHeader) {
  EXPECT_EQ(offError("PLY\n3 1 0\n"), "t.off:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found 'PLY'");
  EXPECT_EQ(offError("# comment\noff\n"), "t.off:2: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found 'off'");
  EXPECT_EQ(offError("3 1 0\n0 0 0\n"), "t.off:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found '3'");
  EXPECT_EQ(offError("OFF3 1 0\n"), "t.off:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found 'OFF3'");
  EXPECT_EQ(offError("STOFF\n"), "t.off:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found 'STOFF'");
}

TEST(ReadOff, RejectsAnEmptyFile) {
  EXPECT_EQ(offError(""), "t.off:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found end of file");
  EXPECT_EQ(offError("# only\n\n"), "t.off:3: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found end of file");
}

TEST(ReadOff, RejectsMissingCounts) {
  EXPECT_EQ(offError("OFF\n"), "t.off:2: error: expected a vertex count, found end of file");
  EXPECT_EQ(offError("OFF\n3\n"), "t.off:2: error: expected a face count (a non-negative integer), found end of line");
  EXPECT_EQ(offError("OFF\n3 1\n"),
            "t.off:2: error: expected an edge count (a non-negative integer), found end of line");
  EXPECT_EQ(offError("OFF BINARY\n"),
            "t.off:1: error: expected a vertex count (a non-negative integer), found 'BINARY'");
}

TEST(ReadOff, RejectsNegativeOrNonIntegerCounts) {
  EXPECT_EQ(offError("OFF\n-1 1 0\n"), "t.off:2: error: expected a vertex count (a non-negative integer), found '-1'");
  EXPECT_EQ(offError("OFF\n3 1.0 0\n"), "t.off:2: error: expected a face count (a non-negative integer), found '1.0'");
  EXPECT_EQ(offError("OFF\n3 1 x\n"), "t.off:2: error: expected an edge count (a non-negative integer), found 'x'");
  EXPECT_EQ(offError("OFF\n3 1 0 0\n"), "t.off:2: error: expected end of line, found '0'");
}

TEST(ReadOff, RejectsZeroCounts) {
  EXPECT_EQ(offError("OFF\n0 0 0\n"), "t.off:2: error: expected at least one vertex, found a vertex count of 0");
  EXPECT_EQ(offError("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
            "t.off:2: error: expected at least one face, found a face count of 0");
}

TEST(ReadOff, RejectsCountsBeyondIntWithoutAllocating) {
  EXPECT_EQ(offError("OFF\n100000000000 1 0\n"),
            "t.off:2: error: expected a vertex count of at most 2147483647, found '100000000000'");
  EXPECT_EQ(offError("OFF\n3 99999999999999999999999 0\n"),
            "t.off:2: error: expected a face count (a non-negative integer), found '99999999999999999999999'");
}

TEST(ReadOff, ImpossibleCountsAreATruncationAtEndOfFileNotAnAllocation) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(offError("OFF\n2000000000 1 0\n0 0 0\n"),
            "t.off:4: error: expected 2000000000 vertices, found end of file");
  EXPECT_EQ(offError(kOffTriangleHeader.substr(0, 4) + "3 2147483647 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "t.off:7: error: expected 2147483647 faces, found end of file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
}

TEST(ReadOff, RejectsTruncatedFiles) {
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0 0\n1 0 0\n"), "t.off:5: error: expected 3 vertices, found end of file");
  EXPECT_EQ(offError("OFF 1 1 0\n"), "t.off:2: error: expected 1 vertex, found end of file");
  EXPECT_EQ(offError(kOffTriangleHeader), "t.off:6: error: expected 1 face, found end of file");
  EXPECT_EQ(offError("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n# c\n"),
            "t.off:9: error: expected 2 faces, found end of file");
}

TEST(ReadOff, RejectsMalformedAndNonFiniteVertices) {
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0 0\n1 abc 0\n"), "t.off:4: error: expected a number, found 'abc'");
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0 0\n1 1.0x 0\n"), "t.off:4: error: expected a number, found '1.0x'");
  for (const std::string bad : {"nan", "inf", "-inf", "1e999"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(offError("OFF\n3 1 0\n0 0 " + bad + "\n"),
              "t.off:3: error: expected a finite number, found '" + bad + "'");
    EXPECT_EQ(offError("NOFF\n3 1 0\n0 0 0 0 " + bad + " 1\n"),
              "t.off:3: error: expected a finite number, found '" + bad + "'");
  }
}

TEST(ReadOff, RejectsTooFewOrTooManyVertexValues) {
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0\n"), "t.off:3: error: expected a z coordinate, found end of line");
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0 0 1\n"), "t.off:3: error: expected end of line, found '1'");
  EXPECT_EQ(offError("NOFF\n3 1 0\n0 0 0 0 1\n"), "t.off:3: error: expected a normal's z component, found end of line");
  EXPECT_EQ(offError("COFF\n3 1 0\n0 0 0 1 1\n"), "t.off:3: error: expected a blue component, found end of line");
  EXPECT_EQ(offError("COFF\n3 1 0\n0 0 0 1 1 1 1 1\n"), "t.off:3: error: expected end of line, found '1'");
}

TEST(ReadOff, RejectsFacesWithFewerThanThreeVertices) {
  EXPECT_EQ(offError(kOffTriangleHeader + "2 0 1\n"),
            "t.off:6: error: expected a face vertex count of at least 3, found '2'");
  EXPECT_EQ(offError(kOffTriangleHeader + "-3 0 1 2\n"),
            "t.off:6: error: expected a face vertex count of at least 3, found '-3'");
  EXPECT_EQ(offError(kOffTriangleHeader + "3.0 0 1 2\n"),
            "t.off:6: error: expected a face vertex count of at least 3, found '3.0'");
}

TEST(ReadOff, RejectsAFaceLineWithFewerIndicesThanItsCount) {
  EXPECT_EQ(offError(kOffTriangleHeader + "4 0 1 2\n"), "t.off:6: error: expected 4 vertex indices, found 3");
  EXPECT_EQ(offError(kOffTriangleHeader + "2000000000 0 1 2\n"),
            "t.off:6: error: expected 2000000000 vertex indices, found 3");
}

TEST(ReadOff, RejectsVertexIndicesOutOfRange) {
  for (const std::string bad : {"3", "-1", "1.5", "x", "2147483648", "99999999999999999999"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 " + bad + "\n"),
              "t.off:6: error: expected a vertex index in 0..2, found '" + bad + "'");
  }
}

TEST(ReadOff, RejectsMalformedFaceColours) {
  EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 2 red\n"), "t.off:6: error: expected a number, found 'red'");
  EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 2 1 1 1 1 1\n"), "t.off:6: error: expected end of line, found '1'");
  EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 2 nan\n"), "t.off:6: error: expected a finite number, found 'nan'");
}

TEST(ReadOff, RejectsDataAfterTheFaces) {
  EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 2\n\n# fine\n3 2 1 0\n"),
            "t.off:9: error: expected end of file, found '3'");
  EXPECT_EQ(offError(kOffTriangleHeader + "3 0 1 2\nOFF\n"), "t.off:7: error: expected end of file, found 'OFF'");
}

TEST(ReadOff, RejectsBinaryBytes) {
  EXPECT_EQ(offError("OFF\n3 1 0\n0 0 0\0\n"s), "t.off:3: error: expected text, found byte 0x00");
  EXPECT_EQ(offError("\xFF\xFEO\0F\0F\0"s),
            "t.off:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark");
}

// ---------------------------------------------------------------------------------------------
// Warnings

TEST(ReadMeshWarnings, CountDegenerateFacesAndUnreferencedVertices) {
  // Face 2 repeats a vertex, face 3 is collinear (zero area); vertices 5 and 6 are unused.
  const ReadMeshResult r =
      obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 9 9 9\nv 8 8 8\n"
          "f 1 2 3\nf 1 2 2\nf 1 2 4\n");
  EXPECT_EQ(r.mesh.faceCount(), 3u);
  EXPECT_EQ(r.warnings.degenerateFaces, 2u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 2u);
}

TEST(ReadMeshWarnings, AreZeroForACleanMesh) {
  const ReadMeshResult r = off(kOffTriangleHeader + "3 0 1 2\n");
  EXPECT_EQ(r.warnings.degenerateFaces, 0u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 0u);
}

TEST(ReadMeshWarnings, CountOffDegenerateFacesAndUnreferencedVertices) {
  const ReadMeshResult r = off("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n3 1 1 2\n");
  EXPECT_EQ(r.warnings.degenerateFaces, 1u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 1u);
}

TEST(ReadMeshWarnings, ConcavePolygonsAreTriangulatedWithoutFolding) {
  // (0,0) (2,0) (2,2) (1,1) (0,2) started at (2,2): the fan from the first corner folded (areas 2 + 2 + 1, one
  // of them clockwise); the polygon's area is 3, and every triangle turns its way (counter-clockwise).
  for (const ReadMeshResult& r : {obj("v 2 2 0\nv 1 1 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nvt 0 0\nf 1/1 2/1 3/1 4/1 5/1\n"),
                                  off("OFF\n5 1 0\n2 2 0\n1 1 0\n0 2 0\n0 0 0\n2 0 0\n5 0 1 2 3 4\n")}) {
    ASSERT_EQ(r.mesh.faceCount(), 3u);
    double area = 0.0;
    for (const Triangle& t : r.mesh.triangles) {
      const Vec3 n = triangleAreaNormal(r.mesh.positions[t[0]], r.mesh.positions[t[1]], r.mesh.positions[t[2]]);
      EXPECT_GT(n.z(), 0.0);
      area += 0.5 * n.norm();
    }
    EXPECT_DOUBLE_EQ(area, 3.0);
    EXPECT_EQ(r.warnings.nonSimplePolygons, 0u);
    EXPECT_EQ(r.warnings.firstNonSimplePolygonLine, 0u);
  }
  // The corner tables follow the triangles' corners.
  const Mesh m = obj("v 2 2 0\nv 1 1 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nvt 0 0\nvt 1 0\nvt 2 0\nvt 3 0\nvt 4 0\n"
                     "f 1/1 2/2 3/3 4/4 5/5\n").mesh;
  EXPECT_EQ(m.cornerTexcoords, m.triangles);
}

TEST(ReadMeshWarnings, CountPolygonsThatAreNotSimpleAndNameTheFirstLine) {
  // Line 6 a convex quad, line 7 a bowtie (self-intersecting), line 8 a triangle, line 9 a twisted quad.
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 1 0.5\n";
  const ReadMeshResult r = obj(vertices + "f 1 2 3 4\nf 1 3 2 4\nf 1 2 3\nf 1 2 3 5\n");
  EXPECT_EQ(r.mesh.faceCount(), 7u);
  EXPECT_EQ(r.warnings.nonSimplePolygons, 2u);
  EXPECT_EQ(r.warnings.firstNonSimplePolygonLine, 7u);
  const ReadMeshResult planar = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n# comment\n\nf 1 3 2 4\n");
  EXPECT_EQ(planar.warnings.nonSimplePolygons, 1u);
  EXPECT_EQ(planar.warnings.firstNonSimplePolygonLine, 8u);
  const ReadMeshResult fromOff = off("OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n4 0 2 1 3\n");
  EXPECT_EQ(fromOff.mesh.faceCount(), 4u);
  EXPECT_EQ(fromOff.warnings.nonSimplePolygons, 1u);
  EXPECT_EQ(fromOff.warnings.firstNonSimplePolygonLine, 8u);
  EXPECT_EQ(obj(vertices + "f 1 2 3\n").warnings.nonSimplePolygons, 0u);
}

// ---------------------------------------------------------------------------------------------
// readMesh on files

class ReadMesh : public ScratchDirTest {
 protected:
  static std::string errorOfPath(const std::string& path) {
    try {
      readMesh(path);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no InputError for " << path;
    return "";
  }
};

TEST_F(ReadMesh, ReadsAnObjFileByItsExtension) {
  const ReadMeshResult r = readMesh(writeText("m.obj", kTriangle + "vt 0 0\nf 1/1 2/1 3/1\n"));
  EXPECT_EQ(r.mesh.triangles, std::vector<Triangle>({{0, 1, 2}}));
  EXPECT_EQ(r.mesh.cornerTexcoords, std::vector<Triangle>({{0, 0, 0}}));
}

TEST_F(ReadMesh, ReadsAnOffFileByItsExtension) {
  const ReadMeshResult r = readMesh(writeText("m.off", kOffTriangleHeader + "3 2 1 0\n"));
  EXPECT_EQ(r.mesh.triangles, std::vector<Triangle>({{2, 1, 0}}));
}

TEST_F(ReadMesh, ExtensionsAreCaseInsensitive) {
  EXPECT_EQ(readMesh(writeText("UPPER.OBJ", kTriangle + "f 1 2 3\n")).mesh.faceCount(), 1u);
  EXPECT_EQ(readMesh(writeText("Mixed.Off", kOffTriangleHeader + "3 0 1 2\n")).mesh.faceCount(), 1u);
}

TEST_F(ReadMesh, ChoosesTheReaderByExtensionNotContent) {
  const std::string path = writeText("actually_off.obj", kOffTriangleHeader + "3 0 1 2\n");
  EXPECT_EQ(errorOfPath(path), path + ":1: error: expected a keyword (v, vt, vn, f, ...), found 'OFF'");
}

TEST_F(ReadMesh, ErrorsNameThePathAndLine) {
  const std::string path = writeText("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  EXPECT_EQ(errorOfPath(path), path + ":3: error: expected a vertex index in 1..2, found '7'");
}

TEST_F(ReadMesh, RejectsOtherExtensions) {
  const std::string x3d = writeText("m.x3d", kTriangle + "f 1 2 3\n");
  EXPECT_EQ(errorOfPath(x3d), x3d + ": error: expected a .obj, .off, .ply, .stl, .gltf or .glb extension, found '.x3d'");
  const std::string none = writeText("mesh", kTriangle + "f 1 2 3\n");
  EXPECT_EQ(errorOfPath(none), none + ": error: expected a .obj, .off, .ply, .stl, .gltf or .glb extension, found none");
  EXPECT_EQ(errorOfPath("model.obj.gz"),
            "model.obj.gz: error: expected a .obj, .off, .ply, .stl, .gltf or .glb extension, found '.gz'");
}

// An OBJ's text under a PLY's name is read as a PLY, and refused as one: the extension decides.
TEST_F(ReadMesh, ChoosesThePlyReaderByExtension) {
  const std::string ply = writeText("m.PLY", kTriangle + "f 1 2 3\n");
  EXPECT_EQ(errorOfPath(ply).rfind(ply + ":1: error: ", 0), 0u) << errorOfPath(ply);
}

TEST_F(ReadMesh, RejectsAMissingFile) {
  const std::string path = (dir_ / "missing.obj").string();
  EXPECT_EQ(errorOfPath(path), path + ": error: cannot open: No such file or directory");
}

TEST_F(ReadMesh, RejectsADirectory) {
  fs::create_directory(dir_ / "folder.obj");
  const std::string path = (dir_ / "folder.obj").string();
  EXPECT_EQ(errorOfPath(path), path + ": error: cannot open: Is a directory");
}

TEST_F(ReadMesh, RejectsAPathThroughAFile) {
  const std::string path = writeText("plain.txt", "text") + "/m.obj";
  EXPECT_EQ(errorOfPath(path), path + ": error: cannot open: Not a directory");
}

TEST_F(ReadMesh, RejectsAnUnreadableFile) {
  withoutPrivileges(dir_, [&] {
    const std::string path = writeText("locked.obj", kTriangle + "f 1 2 3\n");
    fs::permissions(path, fs::perms::none);
    ASSERT_FALSE(std::ifstream(path).good());
    EXPECT_EQ(errorOfPath(path), path + ": error: cannot open: Permission denied");
  });
}

TEST_F(ReadMesh, ReportsWarnings) {
  const ReadMeshResult r = readMesh(writeText("w.obj", kTriangle + "v 4 4 4\nf 1 2 2\nf 1 2 3\n"));
  EXPECT_EQ(r.warnings.degenerateFaces, 1u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 1u);
}

TEST(ReadMeshData, ReadsABlenderStyleObjCubeWithQuadsAndCrlf) {
  const ReadMeshResult r = readMesh(UVTK_TEST_DATA_DIR "/io/cube_quads.obj");
  EXPECT_EQ(r.mesh.vertexCount(), 8u);
  EXPECT_EQ(r.mesh.faceCount(), 12u);
  EXPECT_EQ(r.mesh.cornerTexcoords.size(), 12u);
  EXPECT_EQ(r.mesh.cornerNormals.size(), 12u);
  EXPECT_EQ(r.mesh.triangles[1], Triangle({0, 6, 2}));
  EXPECT_EQ(r.mesh.cornerTexcoords[1], Triangle({0, 2, 3}));
  EXPECT_EQ(r.mesh.cornerNormals[11], Triangle({5, 5, 5}));
  EXPECT_EQ(r.warnings.degenerateFaces, 0u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 0u);
}

TEST(ReadMeshData, ReadsAnOffCubeWithQuads) {
  const ReadMeshResult r = readMesh(UVTK_TEST_DATA_DIR "/io/cube.off");
  EXPECT_EQ(r.mesh.vertexCount(), 8u);
  EXPECT_EQ(r.mesh.faceCount(), 12u);
  EXPECT_EQ(r.mesh.triangles[0], Triangle({0, 3, 2}));
  EXPECT_EQ(r.mesh.triangles[1], Triangle({0, 2, 1}));
  EXPECT_EQ(r.warnings.degenerateFaces, 0u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 0u);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
