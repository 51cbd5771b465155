// PLY: hand-written files of known contents in the three formats, the exact message for each kind
// of bad input, round trips through the writer on generated meshes, and OpenMesh as an independent
// recount of what the writer produces.
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "io/io_fixtures.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "io/split_vertices.h"
#include "meshes/generators.h"
#include "doubles.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the binary test files are built on a little-endian host");

ReadMeshResult read(const std::string& bytes) {
  std::istringstream in(bytes);
  return readPly(in, "t.ply");
}

// The message readPly throws, or "no error".
std::string errorOf(const std::string& bytes) {
  try {
    read(bytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Binary data built value by value in either byte order.
class Bytes {
 public:
  explicit Bytes(bool bigEndian = false) : big_(bigEndian) {}
  template <typename T>
  Bytes& put(T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if (big_) std::reverse(b, b + sizeof(T));
    bytes_.append(b, sizeof(T));
    return *this;
  }
  Bytes& f32(float v) { return put(v); }
  Bytes& f64(double v) { return put(v); }
  Bytes& i32(std::int32_t v) { return put(v); }
  Bytes& u8(std::uint8_t v) { return put(v); }
  const std::string& str() const { return bytes_; }

 private:
  bool big_;
  std::string bytes_;
};

// ---- Files of known contents ----

const char* const kQuadHeader =
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\n"
    "property list uchar int vertex_indices\n"
    "property list uchar float texcoord\n"
    "end_header\n";

// The quad (0,0,0) (1,0,0) (1,1,0) (0,1,0) with per-corner UVs (0.25k, 0.5 + 0.125k), k the corner.
void expectQuad(const ReadMeshResult& r) {
  const Mesh& m = r.mesh;
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2], Vec3(1, 1, 0));
  // Convex: the fan from the first corner.
  ASSERT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
  ASSERT_EQ(m.texcoords.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m.texcoords[std::size_t(k)], Vec3(0.25 * k, 0.5 + 0.125 * k, 0)) << k;
  EXPECT_EQ(m.cornerTexcoords, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_FALSE(m.hasNormals());
  EXPECT_EQ(r.warnings.degenerateFaces, 0u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 0u);
  EXPECT_EQ(r.warnings.nonSimplePolygons, 0u);
}

std::string binaryQuad(bool bigEndian) {
  Bytes b(bigEndian);
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& v : p) b.f32(v[0]).f32(v[1]).f32(v[2]);
  b.u8(4).i32(0).i32(1).i32(2).i32(3).u8(8);
  for (int k = 0; k < 4; ++k) b.f32(0.25f * k).f32(0.5f + 0.125f * k);
  return std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n" +
         kQuadHeader + b.str();
}

TEST(ReadPly, ReadsAnAsciiQuadWithPerCornerTexcoordsAsTwoTriangles) {
  expectQuad(read(std::string("ply\nformat ascii 1.0\ncomment made by hand\n") + kQuadHeader +
                  "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 8 0 0.5 0.25 0.625 0.5 0.75 0.75 0.875\n"));
}

TEST(ReadPly, ReadsTheSameQuadInBinaryLittleAndBigEndian) {
  expectQuad(read(binaryQuad(false)));
  expectQuad(read(binaryQuad(true)));
}

TEST(ReadPly, ReadsVertexTexcoordsNormalsAndDropsColoursAndOtherProperties) {
  // CRLF line ends, obj_info, a colour and a confidence, an edge element read and ignored.
  const ReadMeshResult r = read(
      "ply\r\nformat ascii 1.0\r\nobj_info scanner 3\r\n"
      "element vertex 3\r\n"
      "property double x\r\nproperty double y\r\nproperty double z\r\n"
      "property float nx\r\nproperty float ny\r\nproperty float nz\r\n"
      "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\n"
      "property float confidence\r\nproperty double s\r\nproperty double t\r\n"
      "element face 1\r\nproperty list uchar uint vertex_indices\r\n"
      "element edge 2\r\nproperty int vertex1\r\nproperty int vertex2\r\n"
      "end_header\r\n"
      "0.1 0 0 0 0 1 255 0 0 0.5 0.1 0.2\r\n"
      "1 0 0 0 0 1 0 255 0 0.5 0.3 0.4\r\n"
      "0 1 0 0 0 -1 0 0 255 0.5 0.5 0.6\r\n"
      "3 0 1 2\r\n0 1\r\n1 2\r\n\r\n");
  const Mesh& m = r.mesh;
  EXPECT_EQ(m.positions[0].x(), 0.1);  // a double property keeps the double
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(m.texcoords, (std::vector<Vec3>{{0.1, 0.2, 0}, {0.3, 0.4, 0}, {0.5, 0.6, 0}}));
  EXPECT_EQ(m.cornerTexcoords, m.triangles);
  EXPECT_EQ(m.normals, (std::vector<Vec3>{{0, 0, 1}, {0, 0, 1}, {0, 0, -1}}));
  EXPECT_EQ(m.cornerNormals, m.triangles);
  EXPECT_EQ(r.warnings.vertexColours, 3u);
}

TEST(ReadPly, ReadsAsciiValuesAtTheirDeclaredTypeAsTheBinaryTwinWould) {
  const ReadMeshResult r = read(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty short y\nproperty float64 z\n"
      "element face 1\nproperty list int8 uint16 vertex_index\nend_header\n"
      "0.1 -7 0.1\n1e-50 +3 -0\n2 0 1e-400\n3 0 1 2\n");
  EXPECT_EQ(r.mesh.positions[0], Vec3(double(0.1f), -7, 0.1));
  EXPECT_EQ(r.mesh.positions[1], Vec3(0, 3, 0));  // too small for a float: 0
  EXPECT_TRUE(std::signbit(r.mesh.positions[1].z()));
  EXPECT_EQ(r.mesh.positions[2].z(), 0.0);
}

TEST(ReadPly, TakesTheFirstTexcoordPairOfSUvTextureUvTextureSt) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\n";
  const std::string tail = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const ReadMeshResult uv = read(head + "property float texture_u\nproperty float texture_v\nproperty float x\n"
                                        "property float y\nproperty float z\nproperty float u\nproperty float v\n" +
                                 tail + "9 9 0 0 0 1 2\n9 9 1 0 0 3 4\n9 9 0 1 0 5 6\n3 0 1 2\n");
  EXPECT_EQ(uv.mesh.texcoords[2], Vec3(5, 6, 0));  // u v comes before texture_u texture_v
  const ReadMeshResult textureSt =
      read(head + "property float x\nproperty float y\nproperty float z\nproperty float texture_s\nproperty float texture_t\n" +
           tail + "0 0 0 1 2\n1 0 0 3 4\n0 1 0 5 6\n3 0 1 2\n");
  EXPECT_EQ(textureSt.mesh.texcoords[1], Vec3(3, 4, 0));
}

TEST(ReadPly, FaceTexcoordsWinOverVertexTexcoords) {
  const ReadMeshResult r = read(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float s\nproperty float t\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar double texcoord\nend_header\n"
      "0 0 0 9 9\n1 0 0 9 9\n0 1 0 9 9\n3 0 1 2 6 0.5 0 1 0.5 0 1\n");
  EXPECT_EQ(r.mesh.texcoords, (std::vector<Vec3>{{0.5, 0, 0}, {1, 0.5, 0}, {0, 1, 0}}));
  EXPECT_EQ(r.mesh.cornerTexcoords, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(ReadPly, AcceptsTheVertexElementAfterTheFaceElement) {
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n4 0 1 2 3 8 0 0.5 0.25 0.625 0.5 0.75 0.75 0.875\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  expectQuad(read(ascii));
}

TEST(ReadPly, TriangulatesPolygonsAndCountsThoseThatAreNotSimple) {
  // A concave pentagon (ear-clipped, no fold), then a bow tie (self-intersecting) on line 13.
  const ReadMeshResult r = read(
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n2 0 0\n2 2 0\n1 0.5 0\n0 2 0\n5 0 1 2 3 4\n4 0 1 4 2\n");
  EXPECT_EQ(r.mesh.triangles.size(), 5u);
  EXPECT_EQ(r.warnings.nonSimplePolygons, 1u);
  EXPECT_EQ(r.warnings.firstNonSimplePolygonLine, 16u);
  // The concave pentagon: no triangle of it has negative area (seen from +z).
  for (std::size_t f = 0; f < 3; ++f) {
    const Triangle& t = r.mesh.triangles[f];
    EXPECT_GT(triangleAreaNormal(r.mesh.positions[t[0]], r.mesh.positions[t[1]], r.mesh.positions[t[2]]).z(), 0) << f;
  }
}

TEST(ReadPly, CountsDegenerateFacesAndUnreferencedVertices) {
  const ReadMeshResult r = read(
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n3 0 0 1\n");
  EXPECT_EQ(r.warnings.degenerateFaces, 1u);
  EXPECT_EQ(r.warnings.unreferencedVertices, 1u);
}

// ---- Bad input: one line, the place, what was expected and found ----

const std::string kHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";  // data from line 10
const std::string kVertices = "0 0 0\n1 0 0\n0 1 0\n";

struct BadInput {
  const char* what;
  std::string bytes;
  std::string message;
};

void expectMessages(const std::vector<BadInput>& cases) {
  for (const BadInput& c : cases) EXPECT_EQ(errorOf(c.bytes), c.message) << c.what;
}

TEST(ReadPly, RefusesABadHeaderWithItsLine) {
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string ascii = "ply\nformat ascii 1.0\n";
  expectMessages({
      {"empty", "", "t.ply:1: error: expected 'ply' (the first line of a PLY file), found end of file"},
      {"BOM", "\xEF\xBB\xBFply\nformat ascii 1.0\n", "t.ply:1: error: expected 'ply', found a UTF-8 byte-order mark"},
      {"an OBJ file", "v 0 0 0\nv 1 0 0\n", "t.ply:1: error: expected 'ply' (the first line of a PLY file), found 'v 0 0 0'"},
      {"a binary STL", std::string(80, '\0') + "\x01\x00", "t.ply:1: error: expected 'ply' (the first line of a PLY file), found '" + [] {
         std::string nuls;
         for (int i = 0; i < 40; ++i) nuls += "\\u0000";
         return nuls;
       }() + "...'"},
      {"bad format", "ply\nformat binary 1.0\n",
       "t.ply:2: error: expected a format ascii, binary_little_endian or binary_big_endian, found 'binary'"},
      {"bad version", "ply\nformat ascii 2.0\n", "t.ply:2: error: expected format version 1.0, found '2.0'"},
      {"two formats", ascii + "format ascii 1.0\n", "t.ply:3: error: expected one format line, found a second"},
      {"no format", "ply\n" + vertex, "t.ply:2: error: expected a format line (format ascii 1.0, ...), found 'element'"},
      {"missing end_header", ascii + vertex, "t.ply:7: error: expected 'end_header', found end of file"},
      {"unknown keyword", ascii + "elements vertex 3\n",
       "t.ply:3: error: expected a header keyword (comment, obj_info, format, element, property or end_header), found 'elements'"},
      {"unknown type", ascii + "element vertex 3\nproperty float128 x\n",
       "t.ply:4: error: expected a property type (char, uchar, short, ushort, int, uint, float, double, or int8 ... "
       "float64), found 'float128'"},
      {"float list count", ascii + "element face 1\nproperty list float int vertex_indices\n",
       "t.ply:4: error: expected an integer type for a list count (char, uchar, short, ushort, int, uint, or int8 ... "
       "uint32), found 'float'"},
      {"property first", ascii + "property float x\n", "t.ply:3: error: expected an element line before the first property, found 'property'"},
      {"extra token", ascii + "element vertex 3 4\n", "t.ply:3: error: expected end of line, found '4'"},
      {"negative count", ascii + "element vertex -3\n", "t.ply:3: error: expected an element count (a non-negative integer), found '-3'"},
      {"count past INT_MAX", ascii + "element face 3000000000\n",
       "t.ply:3: error: expected an element count of at most 2147483647, found '3000000000'"},
      {"same element twice", ascii + vertex + "element vertex 1\n", "t.ply:7: error: expected an element name not used before, found 'vertex'"},
      {"same property twice", ascii + "element vertex 3\nproperty float x\nproperty double x\n",
       "t.ply:5: error: expected a property name not used before in element 'vertex', found 'x'"},
      {"element without properties", ascii + "element edge 2\nend_header\n",
       "t.ply:4: error: expected a property of element 'edge' (its count is 2), found 'end_header'"},
      {"control byte", ascii + "comment a\tb\x01\n", "t.ply:3: error: expected text, found byte 0x01"},
      {"no vertex element", ascii + face + "end_header\n", "t.ply:5: error: expected an element 'vertex', found 'end_header'"},
      {"no face element", ascii + vertex + "end_header\n",
       "t.ply:7: error: expected an element 'face' (a point cloud is not a mesh), found 'end_header'"},
      {"triangle strips", ascii + vertex + "element tristrips 1\nproperty list int int vertex_indices\nend_header\n",
       "t.ply:7: error: expected an element 'face', found 'element tristrips' (triangle strips are not read: save the "
       "mesh with faces, e.g. from MeshLab)"},
      {"no faces", ascii + vertex + "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
       "t.ply:7: error: expected at least one face, found 'element face 0'"},
      {"no z", ascii + "element vertex 3\nproperty float x\nproperty float y\n" + face + "end_header\n",
       "t.ply:3: error: expected properties x, y and z in element 'vertex', found no 'z'"},
      {"x a list", ascii + "element vertex 3\nproperty list uchar float x\n" + face + "end_header\n",
       "t.ply:4: error: expected a scalar property 'x', found a list"},
      {"half the normals", ascii + vertex + "property float nx\nproperty float ny\n" + face + "end_header\n",
       "t.ply:3: error: expected all or none of nx, ny and nz in element 'vertex', found no 'nz'"},
      {"no indices", ascii + vertex + "element face 1\nproperty int flags\nend_header\n",
       "t.ply:7: error: expected a list vertex_indices (or vertex_index) in element 'face', found none"},
      {"both index lists", ascii + vertex + face + "property list uchar int vertex_index\nend_header\n",
       "t.ply:9: error: expected one of vertex_indices and vertex_index in element 'face', found both"},
      {"float indices", ascii + vertex + "element face 1\nproperty list uchar float vertex_indices\nend_header\n",
       "t.ply:8: error: expected a list of an integer type for 'vertex_indices', found a list of float"},
      {"scalar texcoord", ascii + vertex + face + "property float texcoord\nend_header\n",
       "t.ply:9: error: expected a list 'texcoord' (2 numbers per corner), found a scalar property"},
  });
}

TEST(ReadPly, RefusesBadAsciiDataWithItsLine) {
  const std::string texcoordHead =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n";
  expectMessages({
      {"too few values", kHead + "0 0 0\n1 0\n", "t.ply:11: error: expected a float for property 'z', found end of line"},
      {"too many values", kHead + "0 0 0 7\n", "t.ply:10: error: expected end of line, found '7'"},
      {"not a number", kHead + "0 x 0\n", "t.ply:10: error: expected a float for property 'y', found 'x'"},
      {"nan", kHead + "nan 0 0\n", "t.ply:10: error: expected a finite float for property 'x', found 'nan'"},
      {"beyond a float", kHead + "0 0 1e39\n", "t.ply:10: error: expected a finite float for property 'z', found '1e39'"},
      {"face of 2", kHead + kVertices + "2 0 1\n",
       "t.ply:13: error: expected a face of at least 3 corners, found a face of 2 (a line, not a face)"},
      {"face of 1", kHead + kVertices + "1 0\n",
       "t.ply:13: error: expected a face of at least 3 corners, found a face of 1 (a point, not a face)"},
      {"index past the end", kHead + kVertices + "3 0 1 3\n", "t.ply:13: error: expected a vertex index in 0..2, found '3'"},
      {"negative index", kHead + kVertices + "3 0 -1 2\n", "t.ply:13: error: expected a vertex index in 0..2, found '-1'"},
      {"index not an integer", kHead + kVertices + "3 0 1.0 2\n",
       "t.ply:13: error: expected an int in list 'vertex_indices' (-2147483648..2147483647), found '1.0'"},
      {"list count past the line", kHead + kVertices + "4 0 1 2\n",
       "t.ply:13: error: expected 4 items in list 'vertex_indices', found 3"},
      {"list count beyond its type", kHead + kVertices + "300 0 1 2\n",
       "t.ply:13: error: expected a uchar list count for 'vertex_indices' (0..255), found '300'"},
      {"truncated vertices", kHead + "0 0 0\n1 0 0\n", "t.ply:12: error: expected 3 vertices, found 2 and end of file"},
      {"no face line", kHead + kVertices + "\n", "t.ply:14: error: expected 1 face, found 0 and end of file"},
      {"trailing text", kHead + kVertices + "3 0 1 2\n\nextra\n", "t.ply:15: error: expected end of file, found 'extra'"},
      {"texcoord list too short", texcoordHead + kVertices + "3 0 1 2 4 0 0 1 0\n",
       "t.ply:14: error: expected a texcoord list of 2 numbers per corner (6 for 3 corners), found 4"},
      {"vertex after face, bad index",
       "ply\nformat ascii 1.0\nelement face 2\nproperty list uchar int vertex_indices\nelement vertex 3\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n3 0 1 2\n3 0 2 3\n" + kVertices,
       "t.ply:11: error: expected a vertex index in 0..2, found '3'"},
  });
}

// The binary triangle file: 3 float vertices from byte H, the face (a uchar count, 3 ints) at H + 36.
std::string binaryHead(const std::string& format = "binary_little_endian", const std::string& faceCount = "1") {
  return "ply\nformat " + format + " 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " + faceCount + "\nproperty list uchar int vertex_indices\nend_header\n";
}

Bytes binaryVertices(bool bigEndian = false) {
  Bytes b(bigEndian);
  b.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0);
  return b;
}

TEST(ReadPly, ReadsTheBinaryTriangleTheCatalogueBreaks) {
  const ReadMeshResult r = read(binaryHead() + binaryVertices().u8(3).i32(0).i32(1).i32(2).str());
  EXPECT_EQ(r.mesh.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(r.mesh.triangles, (std::vector<Triangle>{{0, 1, 2}}));
}

TEST(ReadPly, RefusesBadBinaryDataWithTheByteOfTheValue) {
  const std::string head = binaryHead();
  const std::size_t h = head.size();
  const auto at = [&](std::size_t offset) { return "t.ply: byte " + std::to_string(h + offset) + ": error: "; };
  const std::string whole = head + binaryVertices().u8(3).i32(0).i32(1).i32(2).str();
  Bytes nanY = Bytes().f32(0).f32(0).f32(0).f32(1).f32(std::numeric_limits<float>::quiet_NaN());
  const std::string texcoordHead =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n";
  const std::string faceFirst =
      "ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  const std::string doubleHead =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  Bytes doubles(true);
  doubles.f64(0).f64(0).f64(0).f64(1).f64(0).f64(-std::numeric_limits<double>::infinity());
  expectMessages({
      {"no data", head, at(0) + "expected 3 vertices, found 0 and end of file"},
      {"cut inside vertex 1's z", whole.substr(0, h + 22), at(20) + "expected 3 vertices, found 1 and end of file"},
      {"cut before the face", whole.substr(0, h + 36), at(36) + "expected 1 face, found 0 and end of file"},
      {"cut inside the third index", whole.substr(0, h + 47), at(45) + "expected 1 face, found 0 and end of file"},
      {"nan", head + nanY.str(), at(16) + "expected a finite float for property 'y', found nan"},
      {"-inf, big endian double", doubleHead + doubles.str(),
       "t.ply: byte " + std::to_string(doubleHead.size() + 40) + ": error: expected a finite double for property 'z', found -inf"},
      {"index past the end", head + binaryVertices().u8(3).i32(0).i32(1).i32(3).str(),
       at(45) + "expected a vertex index in 0..2, found 3"},
      {"negative index", head + binaryVertices().u8(3).i32(0).i32(-1).i32(2).str(),
       at(41) + "expected a vertex index in 0..2, found -1"},
      {"face of 2", head + binaryVertices().u8(2).i32(0).i32(1).str(),
       at(36) + "expected a face of at least 3 corners, found a face of 2 (a line, not a face)"},
      {"trailing bytes", whole + "xyz", at(49) + "expected end of file after the last element, found 3 more bytes"},
      {"one trailing NUL", whole + std::string(1, '\0'), at(49) + "expected end of file after the last element, found 1 more bytes"},
      {"huge face count in a tiny file", binaryHead("binary_little_endian", "2147483647") + whole.substr(h),
       "t.ply: byte " + std::to_string(h + 9 + 49) + ": error: expected 2147483647 faces, found 1 and end of file"},
      {"list count past INT_MAX",
       "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uint int vertex_indices\nend_header\n" +
           binaryVertices().put(std::uint32_t{4000000000u}).str(),
       "t.ply: byte " + std::to_string(h - 1 + 36) + ": error: expected a list count in 0..2147483647 for 'vertex_indices', found 4000000000"},
      {"huge list count in a tiny file",
       "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list int int vertex_indices\nend_header\n" +
           binaryVertices().i32(2000000000).i32(0).i32(1).i32(2).str(),
       "t.ply: byte " + std::to_string(h - 2 + 52) + ": error: expected 1 face, found 0 and end of file"},
      {"texcoord list of the wrong length", texcoordHead + binaryVertices().u8(3).i32(0).i32(1).i32(2).u8(4).f32(0).f32(0).f32(0).f32(0).str(),
       "t.ply: byte " + std::to_string(texcoordHead.size() + 49) +
           ": error: expected a texcoord list of 2 numbers per corner (6 for 3 corners), found 4"},
      {"face before vertex, bad index", faceFirst + Bytes().u8(3).i32(0).i32(7).i32(2).str() + binaryVertices().str(),
       "t.ply: byte " + std::to_string(faceFirst.size() + 5) + ": error: expected a vertex index in 0..2, found 7"},
      {"nan in an ignored element",
       "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nelement material 1\nproperty float shininess\nend_header\n" +
           binaryVertices().u8(3).i32(0).i32(1).i32(2).f32(std::numeric_limits<float>::infinity()).str(),
       "t.ply: byte " + std::to_string(h + 44 + 49) + ": error: expected a finite float for property 'shininess', found inf"},
  });
}

TEST(ReadPly, FailsFastOnAHugeClaimedCountInATinyFile) {
  // A 2^31 - 1 vertex claim must neither allocate for it nor loop over it.
  std::string head = binaryHead();
  head.replace(head.find("vertex 3") + 7, 1, "2147483647");
  const std::string bytes = head + binaryVertices().str();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(errorOf(bytes), "t.ply: byte " + std::to_string(bytes.size()) +
                                ": error: expected 2147483647 vertices, found 3 and end of file");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

TEST(ReadPly, ReadsTheBinaryVertexElementAfterTheFaceElement) {
  const std::string faceFirst =
      "ply\nformat binary_big_endian 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n";
  Bytes b(true);
  b.u8(4).i32(0).i32(1).i32(2).i32(3).u8(8);
  for (int k = 0; k < 4; ++k) b.f32(0.25f * k).f32(0.5f + 0.125f * k);
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& v : p) b.f32(v[0]).f32(v[1]).f32(v[2]);
  expectQuad(read(faceFirst + b.str()));
}

// ---- Writing ----

std::string written(const Mesh& mesh, const UvMap* uvs, const PlyWriteOptions& options) {
  std::ostringstream out;
  writePly(out, mesh, uvs, options);
  return out.str();
}

TEST(WritePly, WritesSplitVerticesWithUvsAndFlagsInvalidFacesInAComment) {
  // Vertex 0 has two UVs; corner 5 is invalid (its stored UV must not be written).
  UvMap uvs = uvsOf({{0, 0}, {1, 0}, {1, 1}, {0.5, 0}, {1, 1}, {0.25, 0.75}});
  uvs.faceFlags[1] = kFaceInvalid;
  uvs.cornerInvalid[5] = kCornerMiss;
  PlyWriteOptions options;
  options.ascii = true;
  options.header = "made by a test\nsecond line";
  EXPECT_EQ(written(twoTriangles(), &uvs, options),
            "ply\nformat ascii 1.0\ncomment made by a test\ncomment second line\n"
            "comment uvtk: 1 faces have corners without a valid UV (written as s t = 0 0); 0-based face numbers: 1\n"
            "element vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
            "property double s\nproperty double t\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0 0 0\n0 0 0 0.5 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0.5 0 0\n3 0 2 3\n3 1 3 4\n");
}

TEST(WritePly, ContinuesTheInvalidFaceListOnShortHeaderLines) {
  const Mesh mesh = meshes::icosphere(5);  // 20480 faces, all flagged
  UvMap uvs = uvsOf(std::vector<Vec2>(3 * mesh.triangles.size(), Vec2::Zero()));
  std::fill(uvs.faceFlags.begin(), uvs.faceFlags.end(), kFaceInvalid);
  const std::string text = written(mesh, &uvs, {});
  const std::string header = text.substr(0, text.find("end_header"));
  std::istringstream lines(header);
  std::vector<std::string> comments;
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("comment", 0) == 0) comments.push_back(line);
  ASSERT_EQ(comments.size(), 3u);
  EXPECT_EQ(comments[0].rfind("comment uvtk: 20480 faces have corners without a valid UV (written as s t = 0 0); "
                              "0-based face numbers: 0 1 2 ", 0), 0u);
  EXPECT_EQ(comments[0].substr(comments[0].size() - 5), " 9999");
  EXPECT_EQ(comments[1].rfind("comment uvtk: more 0-based face numbers: 10000 10001 ", 0), 0u);
  EXPECT_EQ(comments[1].substr(comments[1].size() - 6), " 19999");
  EXPECT_EQ(comments[2], [] {
    std::string last = "comment uvtk: more 0-based face numbers:";
    for (int f = 20000; f < 20480; ++f) last += " " + std::to_string(f);
    return last;
  }());
  EXPECT_EQ(read(text).mesh.triangles.size(), 20480u);
}

TEST(WritePly, WritesNormalsPerCornerIndexAndTheVertexNormalWhereACornerHasNone) {
  Mesh mesh = twoTriangles();
  mesh.normals = {{0, 0, 1}};
  mesh.cornerNormals = {{0, 0, 0}, {0, -1, 0}};
  PlyWriteOptions options;
  options.ascii = true;
  const std::string text = written(mesh, nullptr, options);
  // The second face's corner at (1, 1, 0) has none: the faces' normals (0, 0, 1) and
  // (0.5, -0.5, 1), summed and divided by |(0.5, -0.5, 2)| = sqrt(4.5).
  EXPECT_EQ(text.substr(text.find("element")),
            "element vertex 5\nproperty double x\nproperty double y\nproperty double z\n"
            "property double nx\nproperty double ny\nproperty double nz\n"
            "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n1 1 0 0.23570226039551587 -0.23570226039551587 0.9428090415820635\n0 1 0.5 0 0 1\n3 0 1 2\n3 0 3 4\n");
}

TEST(WritePly, WritesLittleEndianDoublesAndUcharIntFaces) {
  const UvMap uvs = uvsOf({{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0.1, 1}});
  const std::string bytes = written(twoTriangles(), &uvs, {});
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
      "property double z\nproperty double s\nproperty double t\nelement face 2\n"
      "property list uchar int vertex_indices\nend_header\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  ASSERT_EQ(bytes.size(), header.size() + 4 * 5 * 8 + 2 * 13);
  double value = 0;
  std::memcpy(&value, bytes.data() + header.size() + 3 * 40 + 3 * 8, 8);  // vertex 3's s
  EXPECT_EQ(value, 0.1);
  std::int32_t index = 0;
  std::memcpy(&index, bytes.data() + header.size() + 160 + 13 + 1 + 8, 4);  // face 1's third corner
  EXPECT_EQ(index, 3);
  EXPECT_EQ(bytes[header.size() + 160], 3);
}

// Per-corner UVs from the angle about z, with the faces across the u = 0/1 seam shifted so that their
// corners agree: the seam's vertices get two UVs. Every `invalidEvery`-th face has an invalid corner.
UvMap seamUvs(const Mesh& mesh, std::size_t invalidEvery) {
  const std::size_t faces = mesh.triangles.size();
  UvMap map = uvsOf(std::vector<Vec2>(3 * faces));
  for (std::size_t f = 0; f < faces; ++f) {
    double u[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[std::size_t(mesh.triangles[f][k])];
      u[k] = std::atan2(p.y(), p.x()) / (2 * M_PI) + 0.5;
    }
    const bool across = *std::max_element(u, u + 3) - *std::min_element(u, u + 3) > 0.5;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[std::size_t(mesh.triangles[f][k])];
      map.uv[3 * f + k] = Vec2(across && u[k] < 0.5 ? u[k] + 1 : u[k], p.z() / 3 + 1.0 / 3);
    }
    if (invalidEvery && f % invalidEvery == 0) {
      map.faceFlags[f] = kFaceInvalid;
      map.cornerInvalid[3 * f + 1] = kCornerMiss;
      map.uv[3 * f + 1] = Vec2::Zero();
    }
  }
  return map;
}

void expectRoundTrip(const char* what, const Mesh& mesh, const UvMap& uvs, bool ascii) {
  SCOPED_TRACE(std::string(what) + (ascii ? " ascii" : " binary"));
  PlyWriteOptions options;
  options.ascii = ascii;
  options.header = "generated by a test";
  const ReadMeshResult r = read(written(mesh, &uvs, options));
  const Mesh& back = r.mesh;
  const std::size_t faces = mesh.triangles.size();
  ASSERT_EQ(back.triangles.size(), faces);
  EXPECT_EQ(back.positions.size(), splitVertices(mesh, {&uvs, false, true}).size());
  ASSERT_EQ(back.cornerTexcoords.size(), faces);
  EXPECT_EQ(back.hasNormals(), mesh.hasNormals());
  std::size_t mismatches = 0;
  for (std::size_t c = 0; c < 3 * faces; ++c) {
    const Vec3& p = mesh.positions[std::size_t(mesh.triangles[c / 3][c % 3])];
    const Vec3& q = back.positions[std::size_t(back.triangles[c / 3][c % 3])];
    // A corner without a valid UV comes back without one (its face is listed in the header).
    const int index = back.cornerTexcoords[c / 3][c % 3];
    bool same = (index < 0) == (uvs.cornerInvalid[c] != kCornerValid);
    if (index >= 0) {
      const Vec3& t = back.texcoords[std::size_t(index)];
      same = same && sameBits(t.x(), uvs.uv[c].x()) && sameBits(t.y(), uvs.uv[c].y()) && t.z() == 0;
    }
    for (int a = 0; a < 3; ++a) same = same && sameBits(p[a], q[a]);
    if (mesh.hasNormals()) {
      const Vec3& n = mesh.normals[std::size_t(mesh.cornerNormals[c / 3][c % 3])];
      const Vec3& m = back.normals[std::size_t(back.cornerNormals[c / 3][c % 3])];
      for (int a = 0; a < 3; ++a) same = same && sameBits(n[a], m[a]);
    }
    mismatches += same ? 0 : 1;
  }
  EXPECT_EQ(mismatches, 0u);
}

std::vector<std::pair<const char*, Mesh>> generatedMeshes() {
  return {{"lat-long sphere", meshes::latLongSphere(24, 12)}, {"torus knot", meshes::torusKnot(2, 3, 120, 8)},
          {"bone", meshes::bone(40, 12)},                    {"bumpy blob", meshes::bumpyBlob(2)},
          {"scanned patch", meshes::scannedPatch(3)},        {"torus", meshes::torus(16, 8, 1.0, 0.3)}};
}

TEST(PlyRoundTrip, KeepsPositionsAndPerCornerUvsBitForBitOnGeneratedMeshes) {
  for (const auto& [what, mesh] : generatedMeshes()) {
    const UvMap uvs = seamUvs(mesh, 7);
    // The test means something: the seam splits vertices.
    std::size_t used = checkMesh(mesh).unreferencedVertices;
    EXPECT_GT(splitVertices(mesh, {&uvs, false, true}).size(), mesh.positions.size() - used) << what;
    expectRoundTrip(what, mesh, uvs, false);
    expectRoundTrip(what, mesh, uvs, true);
  }
}

TEST(PlyRoundTrip, ReadsValuesAcrossTheReadBlocksOfALargeFile) {
  // Several megabytes: values and lines straddle the 64 KiB first block and the 1 MiB ones after.
  const Mesh mesh = meshes::icosphere(6);
  const UvMap uvs = seamUvs(mesh, 11);
  expectRoundTrip("icosphere", mesh, uvs, false);
  expectRoundTrip("icosphere", mesh, uvs, true);
}

TEST(PlyRoundTrip, KeepsPerVertexNormals) {
  Mesh mesh = meshes::torusKnot(3, 2, 60, 6);
  mesh.normals = areaWeightedVertexNormals(mesh);
  mesh.cornerNormals = mesh.triangles;
  const UvMap uvs = seamUvs(mesh, 0);
  expectRoundTrip("knot with normals", mesh, uvs, false);
  expectRoundTrip("knot with normals", mesh, uvs, true);
}

// OpenMesh reads what the writer wrote: the same counts and, to float precision, the same positions.
class PlyOpenMesh : public ScratchDirTest {};

TEST_F(PlyOpenMesh, RecountsTheWritersFilesInBinaryAndAscii) {
  for (const auto& [what, mesh] : generatedMeshes()) {
    const UvMap uvs = seamUvs(mesh, 5);
    for (const bool ascii : {false, true}) {
      SCOPED_TRACE(std::string(what) + (ascii ? " ascii" : " binary"));
      PlyWriteOptions options;
      options.ascii = ascii;
      const std::string bytes = written(mesh, &uvs, options);
      const std::string file = writeText("m.ply", bytes);
      const Mesh ours = read(bytes).mesh;
      OpenMesh::PolyMesh_ArrayKernelT<> om;
      ASSERT_TRUE(OpenMesh::IO::read_mesh(om, file));
      ASSERT_EQ(om.n_vertices(), ours.positions.size());
      ASSERT_EQ(om.n_faces(), ours.triangles.size());
      std::size_t far = 0;
      for (const auto v : om.vertices()) {
        const auto& p = om.point(v);
        const Vec3& q = ours.positions[std::size_t(v.idx())];
        for (int a = 0; a < 3; ++a) far += p[a] == static_cast<float>(q[a]) ? 0 : 1;
      }
      EXPECT_EQ(far, 0u);
      std::size_t otherCorners = 0;
      for (const auto f : om.faces()) {
        const Triangle& t = ours.triangles[std::size_t(f.idx())];
        int k = 0;
        for (const auto v : om.fv_range(f)) otherCorners += k < 3 && v.idx() == t[std::size_t(k++)] ? 0 : 1;
      }
      EXPECT_EQ(otherCorners, 0u);
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
