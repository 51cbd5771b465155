// glTF 2.0: hand-made files read with known positions, UVs and windings; a catalogue of bad files
// with their exact messages; the writer's files read back and its JSON checked field by field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/gltf_reader.h"
#include "io/gltf_writer.h"
#include "io/split_vertices.h"
#include "meshes/generators.h"
#include "scratch_dir.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

using nlohmann::json;

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  const auto byte = [&](std::size_t i) { return i < bytes.size() ? static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i])) : 0u; };
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t chunk = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += kAlphabet[(chunk >> 18) & 63];
    out += kAlphabet[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[chunk & 63] : '=';
  }
  return out;
}

// Little-endian values appended to a byte string.
struct Bytes {
  std::string data;
  template <class T>
  Bytes& put(std::initializer_list<T> values) {
    for (const T v : values) data.append(reinterpret_cast<const char*>(&v), sizeof v);
    return *this;
  }
  Bytes& f32(std::initializer_list<float> v) { return put(v); }
  Bytes& u16(std::initializer_list<std::uint16_t> v) { return put(v); }
  Bytes& u32(std::initializer_list<std::uint32_t> v) { return put(v); }
};

// A document and its one buffer, written as .gltf with a data URI or as .glb.
struct Asset {
  json doc;
  std::string bin;

  std::string gltf() const {
    json d = doc;
    d["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
    return d.dump();
  }
  std::string glb() const {
    json d = doc;
    d["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = d.dump(), data = bin;
    text.resize((text.size() + 3) / 4 * 4, ' ');
    data.resize((data.size() + 3) / 4 * 4, '\0');
    Bytes out;
    out.data = "glTF";
    out.u32({2, static_cast<std::uint32_t>(28 + text.size() + data.size()), static_cast<std::uint32_t>(text.size())});
    out.data += "JSON" + text;
    out.u32({static_cast<std::uint32_t>(data.size())});
    out.data += std::string("BIN\0", 4) + data;
    return out.data;
  }
};

json view(std::size_t offset, std::size_t length) { return {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}}; }
json accessor(int bufferView, int componentType, std::size_t count, const char* type) {
  return {{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}};
}

// A unit quad in z = 0 with UVs (glTF's v down) and USHORT indices, placed by a node that scales
// by 2 and moves by (1, 2, 3).
Asset quad() {
  Asset a;
  a.bin = Bytes()
              .f32({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0})
              .f32({0, 0.25f, 1, 0.25f, 1, 1, 0, 1})
              .u16({0, 1, 2, 0, 2, 3})
              .data;
  a.doc = {{"asset", {{"version", "2.0"}}},
           {"bufferViews", {view(0, 48), view(48, 32), view(80, 12)}},
           {"accessors", {accessor(0, 5126, 4, "VEC3"), accessor(1, 5126, 4, "VEC2"), accessor(2, 5123, 6, "SCALAR")}},
           {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}}}}}}},
           {"nodes", {{{"mesh", 0}, {"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}}}},
           {"scenes", {{{"nodes", {0}}}}},
           {"scene", 0}};
  return a;
}

ReadMeshResult readText(const std::string& text) { return readGltf(text, "in.gltf", "", false); }

std::string errorOf(const std::string& bytes, bool binary = false, const std::string& folder = "") {
  try {
    readGltf(bytes, binary ? "in.glb" : "in.gltf", folder, binary);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ReadGltf, ReadsAQuadPlacedByItsNodeWithUvsFlippedToOurV) {
  const ReadMeshResult r = readText(quad().gltf());
  const Mesh& m = r.mesh;
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[0], Vec3(1, 2, 3));
  EXPECT_EQ(m.positions[1], Vec3(3, 2, 3));
  EXPECT_EQ(m.positions[2], Vec3(3, 4, 3));
  EXPECT_EQ(m.positions[3], Vec3(1, 4, 3));
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
  ASSERT_EQ(m.texcoords.size(), 4u);
  EXPECT_EQ(m.texcoords[0], Vec3(0, 0.75, 0));
  EXPECT_EQ(m.texcoords[1], Vec3(1, 0.75, 0));
  EXPECT_EQ(m.texcoords[2], Vec3(1, 0, 0));
  EXPECT_EQ(m.texcoords[3], Vec3(0, 0, 0));
  EXPECT_EQ(m.cornerTexcoords, m.triangles);  // per-vertex attributes
  EXPECT_FALSE(m.hasNormals());
  EXPECT_EQ(r.warnings.skippedPrimitives, 0u);
  EXPECT_EQ(r.warnings.degenerateFaces, 0u);
}

TEST(ReadGltf, ANegativeDeterminantReversesTheWinding) {
  Asset a = quad();
  // x mirrored (column-major), then moved by 5 along x.
  a.doc["nodes"][0] = {{"mesh", 0}, {"matrix", {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1}}};
  const Mesh m = readText(a.gltf()).mesh;
  EXPECT_EQ(m.positions[1], Vec3(4, 0, 0));
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 2, 1}, {0, 3, 2}}));
  EXPECT_EQ(m.cornerTexcoords, m.triangles);
  // Still counter-clockwise seen from +z: the mirrored quad's normal keeps pointing at +z.
  EXPECT_GT(triangleAreaNormal(m.positions[0], m.positions[2], m.positions[1]).z(), 0.0);
}

TEST(ReadGltf, ComposesAChildUnderItsParentAndRotatesByTheQuaternion) {
  Asset a = quad();
  const double h = std::sqrt(0.5);  // a quarter turn about z
  a.doc["nodes"] = {{{"children", {1}}, {"translation", {10, 0, 0}}}, {{"mesh", 0}, {"rotation", {0, 0, h, h}}, {"scale", {2, 1, 1}}}};
  const Mesh m = readText(a.gltf()).mesh;
  // T(10, 0, 0) R(90 degrees) S(2, 1, 1): (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (10, 2, 0).
  EXPECT_NEAR(m.positions[1].x(), 10, 1e-15);
  EXPECT_NEAR(m.positions[1].y(), 2, 1e-15);
  EXPECT_NEAR(m.positions[3].x(), 9, 1e-15);  // (0, 1, 0) -> (-1, 0, 0) -> (9, 0, 0)
  EXPECT_NEAR(m.positions[3].y(), 0, 1e-15);
}

TEST(ReadGltf, TransformsNormalsByTheInverseTransposeAndRenormalises) {
  Asset a = quad();
  const std::size_t at = a.bin.size();
  const float s = std::sqrt(0.5f);
  a.bin += Bytes().f32({s, s, 0, s, s, 0, 0, 0, 1, 0, 0, 1}).data;
  a.doc["bufferViews"].push_back(view(at, 48));
  a.doc["accessors"].push_back(accessor(3, 5126, 4, "VEC3"));
  a.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 3;
  a.doc["nodes"][0] = {{"mesh", 0}, {"scale", {2, 1, 1}}};
  const Mesh m = readText(a.gltf()).mesh;
  ASSERT_EQ(m.normals.size(), 4u);
  // (1, 1, 0) through diag(1/2, 1, 1): (1/2, 1, 0), of length sqrt(5) / 2.
  EXPECT_NEAR(m.normals[0].x(), 1 / std::sqrt(5.0), 1e-7);
  EXPECT_NEAR(m.normals[0].y(), 2 / std::sqrt(5.0), 1e-7);
  EXPECT_EQ(m.normals[2], Vec3(0, 0, 1));
  EXPECT_EQ(m.cornerNormals, m.triangles);
}

TEST(ReadGltf, ConvertsStripsAndFansAndSkipsLines) {
  Asset a = quad();
  // Five positions along a zigzag, read without indices as a strip, a fan and lines.
  const std::size_t at = a.bin.size();
  a.bin += Bytes().f32({0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 2, 0, 0}).data;
  a.doc["bufferViews"].push_back(view(at, 60));
  a.doc["accessors"].push_back(accessor(3, 5126, 5, "VEC3"));
  a.doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 3}}}, {"mode", 5}},
                                       {{"attributes", {{"POSITION", 3}}}, {"mode", 1}},
                                       {{"attributes", {{"POSITION", 3}}}, {"mode", 6}}};
  a.doc["nodes"][0] = {{"mesh", 0}};
  const ReadMeshResult r = readText(a.gltf());
  EXPECT_EQ(r.mesh.positions.size(), 10u);  // each primitive its own vertices
  EXPECT_EQ(r.mesh.triangles, (std::vector<Triangle>{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}, {6, 7, 5}, {7, 8, 5}, {8, 9, 5}}));
  EXPECT_EQ(r.warnings.skippedPrimitives, 1u);
  EXPECT_FALSE(r.mesh.hasTexcoords());
}

TEST(ReadGltf, GivesCornersOfPrimitivesWithoutUvsNoTexcoord) {
  Asset a = quad();
  a.doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}}}, {"indices", 2}},
                                       {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}}};
  const Mesh m = readText(a.gltf()).mesh;
  EXPECT_EQ(m.positions.size(), 8u);
  EXPECT_EQ(m.texcoords.size(), 4u);
  EXPECT_EQ(m.cornerTexcoords, (std::vector<Triangle>{{-1, -1, -1}, {-1, -1, -1}, {0, 1, 2}, {0, 2, 3}}));
}

TEST(ReadGltf, ReadsTheDefaultSceneOrEveryMeshWhenThereIsNone) {
  Asset a = quad();
  a.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 0, 7}}}};
  a.doc["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
  a.doc["scene"] = 1;
  EXPECT_EQ(readText(a.gltf()).mesh.positions[0], Vec3(0, 0, 7));
  a.doc.erase("scene");  // scene 0
  EXPECT_EQ(readText(a.gltf()).mesh.positions[0], Vec3(0, 0, 0));
  a.doc.erase("scenes");
  a.doc.erase("nodes");  // every mesh once, untransformed
  const Mesh m = readText(a.gltf()).mesh;
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2], Vec3(1, 1, 0));
}

TEST(ReadGltf, ReadsQuantizedPositionsAndNormalizedTexcoords) {
  Asset a = quad();
  // Normalized SHORT positions and UNSIGNED_BYTE UVs, each element padded to 4 bytes by byteStride.
  a.bin = Bytes().put<std::int16_t>({0, 0, 0, 0, 0, 32767, 0, 0, -32768, 0, 0, 0}).data;
  a.bin += Bytes().put<std::uint8_t>({0, 255, 0, 0, 51, 0, 0, 0, 0, 0, 0, 0}).data;
  a.doc["bufferViews"] = {view(0, 24), view(24, 12)};
  a.doc["bufferViews"][0]["byteStride"] = 8;
  a.doc["bufferViews"][1]["byteStride"] = 4;
  a.doc["accessors"] = {accessor(0, 5122, 3, "VEC3"), accessor(1, 5121, 3, "VEC2")};
  a.doc["accessors"][0]["normalized"] = true;
  a.doc["accessors"][1]["normalized"] = true;
  a.doc["meshes"][0]["primitives"][0] = {{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}};
  a.doc["nodes"][0] = {{"mesh", 0}};
  // Without the extension, SHORT positions are not glTF.
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /meshes/0/primitives/0/attributes/POSITION: error: expected a VEC3 accessor of FLOAT (with "
            "KHR_mesh_quantization also of BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT), found accessor 0: VEC3 of "
            "normalized SHORT");
  a.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  a.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  const Mesh m = readText(a.gltf()).mesh;
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(m.positions[1], Vec3(0, 1, 0));
  EXPECT_EQ(m.positions[2], Vec3(-1, 0, 0));   // -32768 clamps to -1
  EXPECT_EQ(m.texcoords[0], Vec3(0, 0, 0));    // (0, 255 / 255): v flipped
  EXPECT_EQ(m.texcoords[1], Vec3(0.2, 1, 0));  // (51 / 255, 0)
}

TEST(ReadGltf, ReadsAGlbAndAGltfWithAnExternalBuffer) {
  const Asset a = quad();
  const ReadMeshResult fromText = readText(a.gltf());
  const ReadMeshResult fromGlb = readGltf(a.glb(), "in.glb", "", true);
  EXPECT_EQ(fromGlb.mesh.positions, fromText.mesh.positions);
  EXPECT_EQ(fromGlb.mesh.triangles, fromText.mesh.triangles);
  EXPECT_EQ(fromGlb.mesh.texcoords, fromText.mesh.texcoords);
}

class GltfFiles : public ScratchDirTest {};

TEST_F(GltfFiles, ReadsFilesByPathWithBuffersBesideThem) {
  const Asset a = quad();
  std::filesystem::create_directories(dir_ / "sub");
  std::ofstream(path("quad.glb"), std::ios::binary) << a.glb();
  std::ofstream(path("sub/quad data.bin"), std::ios::binary) << a.bin;
  json doc = a.doc;
  doc["buffers"] = {{{"byteLength", a.bin.size()}, {"uri", "sub/quad%20data.bin"}}};
  writeText("quad.gltf", doc.dump());
  EXPECT_EQ(readMesh(path("quad.glb")).mesh.positions, readMesh(path("quad.gltf")).mesh.positions);
  EXPECT_EQ(readMesh(path("quad.gltf")).mesh.texcoords[0], Vec3(0, 0.75, 0));
  // ".." may lead out of the file's folder: asset folders share buffers so.
  doc["buffers"][0]["uri"] = "../sub/quad%20data.bin";
  writeText("sub/up.gltf", doc.dump());
  EXPECT_EQ(readMesh(path("sub/up.gltf")).mesh.positions.size(), 4u);
  doc["buffers"][0]["uri"] = "sub/quad%20data.bin";
  // A GLB is known by its magic whatever its name.
  std::ofstream(path("quad.bin.gltf"), std::ios::binary) << a.glb();
  EXPECT_EQ(readMesh(path("quad.bin.gltf")).mesh.triangles.size(), 2u);

  // The buffer missing, too short, and named by an absolute path or a URL.
  doc["buffers"][0]["uri"] = "missing.bin";
  writeText("bad.gltf", doc.dump());
  const auto errorOfFile = [&](const std::string& file) {
    try {
      readMesh(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(errorOfFile(path("bad.gltf")),
            path("bad.gltf") + ": /buffers/0: error: cannot read the buffer file 'missing.bin': No such file or directory");
  std::ofstream(path("short.bin"), std::ios::binary) << a.bin.substr(0, 80);
  doc["buffers"][0]["uri"] = "short.bin";
  writeText("bad.gltf", doc.dump());
  EXPECT_EQ(errorOfFile(path("bad.gltf")),
            path("bad.gltf") + ": /buffers/0: error: expected 92 bytes (its byteLength) in 'short.bin', found 80");
  doc["buffers"][0]["uri"] = path("sub/quad data.bin");
  writeText("bad.gltf", doc.dump());
  EXPECT_EQ(errorOfFile(path("bad.gltf")), path("bad.gltf") +
                                               ": /buffers/0: error: expected a relative uri or a base64 data: uri, found "
                                               "the absolute path '" +
                                               path("sub/quad data.bin").substr(0, 40) + "...'");
  doc["buffers"][0]["uri"] = "https://example.com/quad.bin";
  writeText("bad.gltf", doc.dump());
  EXPECT_EQ(errorOfFile(path("bad.gltf")),
            path("bad.gltf") + ": /buffers/0: error: expected a relative uri or a base64 data: uri, found 'https://example.com/quad.bin'");
  EXPECT_EQ(errorOfFile(path("none.gltf")), path("none.gltf") + ": error: cannot open: No such file or directory");
}

// ---- The catalogue of bad files ----

TEST(ReadGltf, RefusesBrokenGlbContainers) {
  const std::string glb = quad().glb();
  const std::string size = std::to_string(glb.size());
  EXPECT_EQ(errorOf(glb.substr(0, glb.size() - 4), true),
            "in.glb: byte " + std::to_string(glb.size() - 4) + ": error: expected 4 more bytes (the GLB header's length is " +
                size + "), found end of file");
  EXPECT_EQ(errorOf(glb + "abcd", true),
            "in.glb: byte " + size + ": error: expected end of file (the GLB header's length is " + size + "), found 4 more bytes");
  EXPECT_EQ(errorOf(glb.substr(0, 7), true), "in.glb: byte 7: error: expected a 12-byte GLB header, found end of file");
  EXPECT_EQ(errorOf("GLTF" + glb.substr(4), true), "in.glb: byte 0: error: expected the GLB magic 'glTF', found 0x46544C47");
  std::string v1 = glb;
  v1[4] = 1;
  EXPECT_EQ(errorOf(v1, true), "in.glb: byte 4: error: expected GLB version 2, found 1");
  std::string bin = glb;
  std::memcpy(&bin[16], "BIN", 4);
  EXPECT_EQ(errorOf(bin, true), "in.glb: byte 16: error: expected the first chunk to be of type JSON (0x4E4F534A), found 0x004E4942");
  std::string longChunk = glb;
  const std::uint32_t claimed = static_cast<std::uint32_t>(glb.size());
  std::memcpy(&longChunk[12], &claimed, 4);
  EXPECT_EQ(errorOf(longChunk, true), "in.glb: byte " + size + ": error: expected the chunk's " + size +
                                          " bytes, found end of file after " + std::to_string(glb.size() - 20));
  std::string odd = glb;
  std::uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, &glb[12], 4);
  --jsonLength;
  std::memcpy(&odd[12], &jsonLength, 4);
  EXPECT_EQ(errorOf(odd, true),
            "in.glb: byte 12: error: expected a chunk length that is a multiple of 4, found " + std::to_string(jsonLength));
}

TEST(ReadGltf, RefusesBadJsonWithItsLine) {
  EXPECT_EQ(errorOf("{\n\"asset\": {\"version\": \"2.0\"},,\n}"),
            "in.gltf:2: error: invalid JSON at column 29: syntax error while parsing object key - unexpected ','; expected "
            "string literal");
  EXPECT_EQ(errorOf("{\"asset\": {}}"), "in.gltf: error: \"asset\" object not found in .gltf or not an object type");
  EXPECT_EQ(errorOf(std::string(300, '[') + std::string(300, ']')),
            "in.gltf:1: error: expected JSON nested at most 256 levels deep, found deeper");
  Asset a = quad();
  a.doc["asset"]["version"] = "1.0";
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /asset/version: error: expected a glTF version 2.x, found '1.0'");
}

TEST(ReadGltf, RefusesBuffersAndViewsThatDoNotHoldTheirData) {
  Asset a = quad();
  json d = a.doc;
  d["buffers"] = {{{"byteLength", 96}, {"uri", "data:application/octet-stream;base64," + base64(a.bin)}}};
  EXPECT_EQ(errorOf(d.dump()), "in.gltf: /buffers/0/uri: error: expected base64 data of exactly its byteLength, found other data");
  d["buffers"][0]["uri"] = "quad.bin";
  EXPECT_EQ(errorOf(d.dump()),
            "in.gltf: /buffers/0: error: cannot read the buffer file 'quad.bin': the input has no folder to find it in");

  a.doc["bufferViews"][2]["byteOffset"] = 84;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /bufferViews/2: error: expected its 12 bytes from byteOffset 84 within buffer 0 (92 bytes), found them past its end");
  a = quad();
  a.doc["accessors"][0]["count"] = 5;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /accessors/0: error: expected its 5 elements of 12 bytes within bufferView 0 (48 bytes), found them past its end");
  a = quad();
  a.doc["accessors"][1]["byteOffset"] = 4;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /accessors/1: error: expected its 4 elements of 8 bytes within bufferView 1 (32 bytes from byteOffset 4), "
            "found them past its end");
  a = quad();
  a.doc["accessors"][0]["bufferView"] = 7;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /accessors/0/bufferView: error: expected a bufferView index in 0..2, found 7");
  a.doc["accessors"][0].erase("bufferView");
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /accessors/0: error: expected a bufferView, found none (an accessor without one holds zeros; uvtk reads none)");
  a = quad();
  a.doc["bufferViews"][0]["buffer"] = 1;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /bufferViews/0/buffer: error: expected a buffer index in 0..0, found 1");
  a = quad();
  a.doc["accessors"][0]["count"] = 0;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /accessors/0/count: error: expected at least 1 element, found 0");
  a = quad();
  a.doc["bufferViews"][0]["byteStride"] = 8;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /bufferViews/0/byteStride: error: expected at least 12 (the element size of accessor 0), found 8");
  a = quad();
  a.doc["accessors"][0]["count"] = std::numeric_limits<std::uint64_t>::max();  // no overflow in the bounds
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /accessors/0: error: expected its 18446744073709551615 elements of 12 bytes within bufferView 0 (48 "
            "bytes), found them past its end");
}

TEST(ReadGltf, RefusesBadIndicesModesAndAttributes) {
  Asset a = quad();
  a.bin.replace(80 + 10, 2, Bytes().u16({7}).data);
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /meshes/0/primitives/0/indices: error: expected vertex indices below 4 (the POSITION count), found 7 at element 5");
  a = quad();
  a.doc["meshes"][0]["primitives"][0]["mode"] = 9;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /meshes/0/primitives/0/mode: error: expected a primitive mode in 0..6, found 9");
  a.doc["meshes"][0]["primitives"][0]["mode"] = 3;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: error: expected at least one triangle primitive in the scene, found none (1 primitive of points or lines skipped)");
  a = quad();
  a.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /meshes/0/primitives/0/attributes: error: expected a POSITION attribute, found none");
  a = quad();
  a.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /meshes/0/primitives/0/attributes/TEXCOORD_0: error: expected a VEC2 accessor of FLOAT, normalized "
            "UNSIGNED_BYTE or normalized UNSIGNED_SHORT (with KHR_mesh_quantization also of BYTE, UNSIGNED_BYTE, SHORT or "
            "UNSIGNED_SHORT), found accessor 0: VEC3 of FLOAT");
  a = quad();
  a.doc["accessors"][2]["componentType"] = 5126;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /meshes/0/primitives/0/indices: error: expected a SCALAR accessor of UNSIGNED_BYTE, UNSIGNED_SHORT or "
            "UNSIGNED_INT, not normalized, found accessor 2: SCALAR of FLOAT");
  a = quad();
  a.doc["accessors"][2]["count"] = 5;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /meshes/0/primitives/0/indices: error: expected a multiple of 3 vertices for TRIANGLES, found 5");
  a = quad();
  a.doc["accessors"][1]["count"] = 3;
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /meshes/0/primitives/0/attributes/TEXCOORD_0: error: expected 4 elements (the POSITION count), found 3");
  a = quad();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  a.bin.replace(2 * 12 + 4, 4, Bytes().f32({nan}).data);
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /accessors/0: error: expected finite numbers, found nan in element 2");
  a = quad();
  a.doc["accessors"][0]["sparse"] = {{"count", 1},
                                     {"indices", {{"bufferView", 2}, {"componentType", 5123}}},
                                     {"values", {{"bufferView", 0}}}};
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /accessors/0/sparse: error: sparse accessors are not supported");
}

TEST(ReadGltf, RefusesExtensionsItCannotReadAndBadNodeGraphs) {
  Asset a = quad();
  a.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  a.doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /extensionsRequired/1: error: the file requires the extension 'KHR_draco_mesh_compression', which uvtk "
            "does not read (it reads KHR_mesh_quantization; KHR_texture_transform moves no vertex)");
  a = quad();
  a.doc["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /nodes/1/children/0: error: node 0 is reached a second time (a cycle, or a child of two parents); uvtk "
            "reads node trees");
  a.doc["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
  a.doc["scenes"][0]["nodes"] = {0, 1};
  EXPECT_EQ(errorOf(a.gltf()),
            "in.gltf: /nodes/1/children/0: error: node 2 is reached a second time (a cycle, or a child of two parents); uvtk "
            "reads node trees");
  a.doc["scenes"][0]["nodes"] = {5};
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /scenes/0/nodes/0: error: expected a node index in 0..2, found 5");
  a = quad();
  a.doc["scene"] = 2;
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /scene: error: expected a scene index in 0..0, found 2");
  a = quad();
  a.doc["nodes"][0]["rotation"] = {0, 0, 0, 2};
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /nodes/0/rotation: error: expected a unit quaternion, found one of length 2.000000");
  a = quad();
  a.doc["nodes"][0] = {{"mesh", 0}, {"matrix", {1, 0, 0}}};
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /nodes/0/matrix: error: expected 16 numbers, found 3");
  // A chain of nodes deeper than the limit.
  a.doc["nodes"] = json::array();
  for (int n = 0; n < 1001; ++n) a.doc["nodes"].push_back({{"children", {n + 1}}});
  a.doc["nodes"].push_back({{"mesh", 0}});
  EXPECT_EQ(errorOf(a.gltf()), "in.gltf: /nodes/999/children/0: error: expected nodes nested at most 1000 deep, found deeper");
}

TEST(ReadGltf, RefusesSceneInstancesFarBeyondTheInputsSize) {
  // 2^12 nodes, each instancing a mesh of 2^9 primitives of the quad: 2^21 primitive instances.
  Asset a = quad();
  json primitives = json::array();
  for (int p = 0; p < 512; ++p) primitives.push_back(a.doc["meshes"][0]["primitives"][0]);
  a.doc["meshes"][0]["primitives"] = primitives;
  a.doc["nodes"] = json::array();
  a.doc["scenes"][0]["nodes"] = json::array();
  for (int n = 0; n < 4096; ++n) {
    a.doc["nodes"].push_back({{"mesh", 0}});
    a.doc["scenes"][0]["nodes"].push_back(n);
  }
  const std::string text = a.gltf();
  EXPECT_EQ(errorOf(text), "in.gltf: error: expected at most " + std::to_string(64 * (text.size() + a.bin.size())) +
                               " vertices and indices in all mesh instances of the scene (64 per input byte), found " +
                               std::to_string(4096 * 512 * 10));
}

// ---- The writer ----

// Per-corner UVs of a sphere with a seam: u from the corner's longitude, pushed past 1 on faces
// that straddle the seam, so the corners at the seam differ from face to face.
UvMap seamUvs(const Mesh& mesh) {
  UvMap uvs;
  for (const Triangle& t : mesh.triangles) {
    double u[3];
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.positions[static_cast<std::size_t>(t[k])];
      u[k] = std::atan2(p.y(), p.x()) / (2 * kPi);
      if (u[k] < 0) u[k] += 1;
    }
    const bool straddles = std::max({u[0], u[1], u[2]}) - std::min({u[0], u[1], u[2]}) > 0.5;
    for (int k = 0; k < 3; ++k) {
      if (straddles && u[k] < 0.5) u[k] += 1;
      const Vec3& p = mesh.positions[static_cast<std::size_t>(t[k])];
      uvs.uv.emplace_back(u[k], std::acos(std::clamp(p.z(), -1.0, 1.0)) / kPi);
    }
    uvs.faceFlags.push_back(kFaceOk);
  }
  uvs.cornerInvalid.assign(uvs.uv.size(), 0);
  return uvs;
}

// The read mesh has, corner by corner, the written mesh's positions and UVs as float32 carries them.
void expectSameCorners(const Mesh& written, const UvMap& uvs, const Mesh& read) {
  ASSERT_EQ(read.triangles.size(), written.triangles.size());
  ASSERT_TRUE(read.hasTexcoords());
  EXPECT_EQ(read.positions.size(), splitVertices(written, {&uvs, false, true}).size());
  for (std::size_t f = 0; f < written.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = written.positions[static_cast<std::size_t>(written.triangles[f][k])];
      const Vec3& q = read.positions[static_cast<std::size_t>(read.triangles[f][k])];
      for (int a = 0; a < 3; ++a) ASSERT_EQ(q[a], static_cast<double>(static_cast<float>(p[a]))) << "face " << f;
      const Vec2& uv = uvs.uv[3 * f + k];
      const Vec3& t = read.texcoords[static_cast<std::size_t>(read.cornerTexcoords[f][k])];
      ASSERT_EQ(t.x(), static_cast<double>(static_cast<float>(uv.x()))) << "face " << f;
      ASSERT_EQ(t.y(), 1.0 - static_cast<double>(static_cast<float>(1.0 - uv.y()))) << "face " << f;
    }
}

std::string glbOf(const Mesh& mesh, const UvMap* uvs, const GltfWriteOptions& options = {}) {
  std::ostringstream out;
  writeGlb(out, mesh, uvs, options);
  return out.str();
}

json jsonOfGlb(const std::string& glb) {
  std::uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  return json::parse(glb.substr(20, length));
}

TEST(WriteGltf, GlbRoundTripKeepsSeamsCornerByCorner) {
  const Mesh sphere = meshes::latLongSphere(24, 12);
  const UvMap uvs = seamUvs(sphere);
  const std::size_t split = splitVertices(sphere, {&uvs, false, true}).size();
  ASSERT_GT(split, sphere.positions.size());  // the seam's vertices are split
  const ReadMeshResult read = readGltf(glbOf(sphere, &uvs), "out.glb", "", true);
  expectSameCorners(sphere, uvs, read.mesh);
  EXPECT_EQ(read.warnings.unreferencedVertices, 0u);
}

TEST_F(GltfFiles, GltfAndBinRoundTripOnMeshesLikeReal) {
  for (const Mesh& mesh : {meshes::torusKnot(2, 3, 64, 8), meshes::scannedPatch(2), meshes::cylinder(16, 2, 1, 3, true)}) {
    const UvMap uvs = seamUvs(mesh);
    {
      std::ofstream text(path("m.gltf"), std::ios::binary), binary(path("m data.bin"), std::ios::binary);
      writeGltf(text, binary, "m data.bin", mesh, &uvs);
    }
    EXPECT_NE(readText(path("m.gltf")).find("\"uri\": \"m%20data.bin\""), std::string::npos);
    expectSameCorners(mesh, uvs, readMesh(path("m.gltf")).mesh);
  }
}

TEST(WriteGltf, WritesTheDocumentItsReaderAndTheValidatorExpect) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0.1, 2, -3}, {0, 1, 0}, {9, 9, 9}};  // vertex 4 unused
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  UvMap uvs;
  uvs.uv = {{0, 0}, {1, 0}, {0.5, 1}, {0, 0}, {0.5, 0.25}, {0, 1}};  // vertex 2 split
  uvs.faceFlags = {kFaceOk, kFaceInvalid};
  uvs.cornerInvalid = {0, 0, 0, kCornerMiss, 0, 0};
  GltfWriteOptions options;
  options.generator = "uvtk test";
  const json doc = jsonOfGlb(glbOf(m, &uvs, options));
  EXPECT_EQ(doc["asset"], json({{"version", "2.0"}, {"generator", "uvtk test"}}));
  EXPECT_EQ(doc["scene"], 0);
  EXPECT_EQ(doc["scenes"], json::parse(R"([{"nodes": [0]}])"));
  EXPECT_EQ(doc["nodes"], json::parse(R"([{"mesh": 0}])"));
  EXPECT_EQ(doc["meshes"], json::parse(R"([{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2}],
                                             "extras": {"uvtk": {"invalid_faces": [1]}}}])"));
  // Five split vertices: 60 bytes of positions, 40 of UVs, 6 indices of 2 bytes.
  EXPECT_EQ(doc["bufferViews"], json::parse(R"([{"buffer": 0, "byteOffset": 0, "byteLength": 60, "target": 34962},
                                                  {"buffer": 0, "byteOffset": 60, "byteLength": 40, "target": 34962},
                                                  {"buffer": 0, "byteOffset": 100, "byteLength": 12, "target": 34963}])"));
  EXPECT_EQ(doc["buffers"], json::parse(R"([{"byteLength": 112}])"));
  EXPECT_EQ(doc["accessors"][0]["count"], 5);
  EXPECT_EQ(doc["accessors"][0]["type"], "VEC3");
  EXPECT_EQ(doc["accessors"][0]["min"], json({0.0, 0.0, -3.0}));
  EXPECT_EQ(doc["accessors"][0]["max"], json({1.0, 2.0, 0.0}));
  EXPECT_EQ(doc["accessors"][1]["min"], json({0.0, 0.0}));
  EXPECT_EQ(doc["accessors"][1]["max"], json({1.0, 1.0}));
  EXPECT_EQ(doc["accessors"][2], json::parse(R"({"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"})"));
  // A min or max that a float rounds: the float's value, exactly.
  m.positions[0].x() = 0.3;
  m.positions[1].x() = 0.3;
  m.positions[2].z() = -0.1;
  const json rounded = jsonOfGlb(glbOf(m, &uvs));
  EXPECT_EQ(rounded["accessors"][0]["max"][0].get<double>(), static_cast<double>(0.3f));
  EXPECT_EQ(rounded["accessors"][0]["min"][2].get<double>(), static_cast<double>(-0.1f));
  EXPECT_EQ(rounded["asset"], json({{"version", "2.0"}}));
}

TEST(WriteGltf, IndicesAreUnsignedShortUpTo65535VerticesAndUnsignedIntBeyond) {
  Mesh m;
  for (int i = 0; i < 65535; ++i) m.positions.emplace_back(i, i % 7, 0);
  for (int i = 0; i < 65535; i += 3) m.triangles.push_back({i, i + 1, i + 2});
  EXPECT_EQ(jsonOfGlb(glbOf(m, nullptr))["accessors"][1]["componentType"], 5123);
  m.positions.emplace_back(-1, -1, -1);
  m.triangles.push_back({65533, 65534, 65535});
  const std::string glb = glbOf(m, nullptr);
  EXPECT_EQ(jsonOfGlb(glb)["accessors"][1]["componentType"], 5125);
  const Mesh read = readGltf(glb, "out.glb", "", true).mesh;
  EXPECT_EQ(read.positions.size(), 65536u);
  EXPECT_EQ(read.triangles.back(), (Triangle{65533, 65534, 65535}));
  EXPECT_EQ(read.positions[65535], Vec3(-1, -1, -1));
}

TEST(WriteGltf, WritesUnitNormalsFallingBackToTheVertexNormal) {
  Mesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {5, 5, 5}};
  m.triangles = {{0, 1, 2}, {3, 3, 3}};  // the second has no area: its vertex no normal
  m.normals = {{0, 3, 0}};
  m.cornerNormals = {{0, -1, -1}, {-1, -1, -1}};
  const json doc = jsonOfGlb(glbOf(m, nullptr));
  EXPECT_EQ(doc["meshes"][0]["primitives"][0]["attributes"], json::parse(R"({"POSITION": 0, "NORMAL": 1})"));
  const Mesh read = readGltf(glbOf(m, nullptr), "out.glb", "", true).mesh;
  ASSERT_EQ(read.normals.size(), 4u);
  EXPECT_EQ(read.normals[static_cast<std::size_t>(read.cornerNormals[0][0])], Vec3(0, 1, 0));  // the file's, unit
  EXPECT_EQ(read.normals[static_cast<std::size_t>(read.cornerNormals[0][1])], Vec3(0, 0, 1));  // the face's
  EXPECT_EQ(read.normals[static_cast<std::size_t>(read.cornerNormals[1][0])], Vec3(0, 0, 1));  // none: +z
  // Vertex normals from the caller when the mesh has none.
  m.normals.clear();
  m.cornerNormals.clear();
  const std::vector<Vec3> given = {{1, 0, 0}, {0, 0, -2}, {0, 0, 0}, {0, 0, 0}};
  GltfWriteOptions options;
  options.vertexNormals = &given;
  const Mesh withGiven = readGltf(glbOf(m, nullptr, options), "out.glb", "", true).mesh;
  EXPECT_EQ(withGiven.normals, (std::vector<Vec3>{{1, 0, 0}, {0, 0, -1}, {0, 0, 1}, {0, 0, 1}}));
}

TEST(WriteGltf, RefusesUvsBeyondFloat32BeforeWritingAnything) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  UvMap uvs;
  uvs.uv = {{0, 0}, {-1e300, 0}, {0, 1}};
  uvs.faceFlags = {kFaceOk};
  uvs.cornerInvalid = {0, 0, 0};
  GltfWriteOptions options;
  options.name = "out.glb";
  std::ostringstream out, text, binary;
  try {
    writeGlb(out, m, &uvs, options);
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "out.glb: error: cannot write: the UV (-1e+300, 0.0) of face 0 corner 1 is beyond glTF's "
                           "float32 range (magnitude at most 3.40282347e+38)");
  }
  EXPECT_TRUE(out.str().empty());
  EXPECT_THROW(writeGltf(text, binary, "out.bin", m, &uvs, options), OutputError);
  EXPECT_TRUE(text.str().empty() && binary.str().empty());
}

// A mesh of a size float32 cannot hold (1e-200 across: zeros; 1e39: beyond its range) or whose
// squared lengths would leave it is written divided by a power of two, the node's uniform scale,
// and reads back to float32's precision at its size. The rule's edge: coordinates in [2^-62, 2^63)
// are written as they are.
TEST(WriteGltf, AMeshOfAnySizeIsWrittenAtAPowerOfTwoScaleAndReadsBack) {
  for (const double size : {1e-300, 1e-200, 1e-40, 1e-20, 1e20, 1e39, 1e300}) {
    Mesh mesh = meshes::torusKnot(2, 3, 64, 8);
    for (Vec3& p : mesh.positions) p *= size;
    double largest = 0.0;
    for (const Vec3& p : mesh.positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    const std::string glb = glbOf(mesh, nullptr);
    const json node = jsonOfGlb(glb)["nodes"][0];
    EXPECT_FALSE(node.contains("translation")) << size;
    const double scale = std::ldexp(1.0, std::ilogb(largest));
    ASSERT_TRUE(node.contains("scale")) << size;
    EXPECT_EQ(node["scale"], json::array({scale, scale, scale})) << size;
    const Mesh read = readGltf(glb, "out.glb", "", true).mesh;
    ASSERT_EQ(read.positions.size(), mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (int a = 0; a < 3; ++a)  // the coordinate divided by the scale, rounded to float32, times the scale
        ASSERT_EQ(read.positions[v][a], double(float(mesh.positions[v][a] / scale)) * scale) << size << " vertex " << v;
  }
  Mesh m;
  m.triangles = {{0, 1, 2}};
  const auto nodeFor = [&](double largest) {
    m.positions = {{-largest, 0, 0}, {largest, 0, 0}, {0, largest / 2, 0}};
    return jsonOfGlb(glbOf(m, nullptr))["nodes"][0];
  };
  EXPECT_FALSE(nodeFor(0x1p63 * (1 - 0x1p-53)).contains("scale"));
  EXPECT_EQ(nodeFor(0x1p63)["scale"][0], 0x1p63);
  EXPECT_FALSE(nodeFor(0x1p-62).contains("scale"));
  EXPECT_EQ(nodeFor(0x1p-62 * (1 - 0x1p-53))["scale"][0], 0x1p-63);
  EXPECT_FALSE(nodeFor(1.0).contains("scale"));
}

// The centre of the mesh's bounding box, as the writer's rule names it.
Vec3 boxCentre(const Mesh& mesh) {
  Vec3 lo = mesh.positions[0], hi = lo;
  for (const Vec3& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return 0.5 * lo + 0.5 * hi;
}

// A mesh far from the origin is written relative to its box's centre, the node's translation: read
// back, every corner lies within float32's rounding at the mesh's size, where writing the far
// coordinates themselves as float32 moves them by up to an eighth of a unit (a torus knot 10 across at
// 2e6: 4,866 of the hostile knot's 29,237 faces collapsed). Beyond float32's range (1e39) it can be
// written at all.
TEST(WriteGltf, AMeshFarFromTheOriginIsWrittenRelativeToItsCentreAndKeepsItsShape) {
  for (const Vec3& offset : {Vec3(1e6, -2e6, 3e5), Vec3(-7e12, 0.0, 5.0), Vec3(1e39, 2e39, -3e39)}) {
    Mesh mesh = meshes::torusKnot(2, 3, 96, 8);
    for (Vec3& p : mesh.positions) p += offset;
    const UvMap uvs = seamUvs(mesh);
    const std::string glb = glbOf(mesh, &uvs);
    const json doc = jsonOfGlb(glb);
    const Vec3 centre = boxCentre(mesh);
    ASSERT_TRUE(doc["nodes"][0].contains("translation")) << offset.transpose();
    for (int a = 0; a < 3; ++a) EXPECT_EQ(doc["nodes"][0]["translation"][a].get<double>(), centre[a]);
    // POSITION's bounds are the floats written: within the knot's own half-size (about 3.4).
    for (int a = 0; a < 3; ++a) {
      EXPECT_LT(std::fabs(doc["accessors"][0]["min"][a].get<double>()), 4.0);
      EXPECT_LT(std::fabs(doc["accessors"][0]["max"][a].get<double>()), 4.0);
    }
    const Mesh read = readGltf(glb, "out.glb", "", true).mesh;
    ASSERT_EQ(read.triangles.size(), mesh.triangles.size());
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.positions[std::size_t(mesh.triangles[f][k])];
        const Vec3& q = read.positions[std::size_t(read.triangles[f][k])];
        for (int a = 0; a < 3; ++a) {
          // Half a float32 ulp of a coordinate below 4 (2^-23), then the reader's one double rounding.
          const double bound = 0x1p-23 + std::fabs(centre[a]) * 0x1p-52;
          ASSERT_LE(std::fabs(q[a] - p[a]), bound) << "face " << f << " offset " << offset.transpose();
        }
      }
  }
}

// The rule's edge: a box whose centre is more than 1.5 times its largest side from the origin (in
// its largest coordinate) is moved; one at exactly 1.5 times, or about the origin, is not, and its
// positions are exactly their float32 values.
TEST(WriteGltf, OnlyAMeshFartherThanOneAndAHalfSidesFromTheOriginIsMoved) {
  Mesh m;
  m.triangles = {{0, 1, 2}};
  const auto written = [&](double x0) {
    m.positions = {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0, 0.5, 0.25}};
    return jsonOfGlb(glbOf(m, nullptr))["nodes"][0];
  };
  EXPECT_FALSE(written(1.0).contains("translation"));         // centre 1.5, side 1
  EXPECT_FALSE(written(-2.0).contains("translation"));        // centre -1.5
  EXPECT_EQ(written(1.0 + 0x1p-20)["translation"], json::array({1.5 + 0x1p-20, 0.25, 0.125}));
  EXPECT_EQ(written(-2.0 - 0x1p-20)["translation"], json::array({-1.5 - 0x1p-20, 0.25, 0.125}));
  EXPECT_FALSE(written(-0.5).contains("translation"));        // about the origin
  m.positions = {{0.1, 0.2, 0.3}, {1.1, 0.2, 0.3}, {0.1, 0.7, 0.3}};
  const Mesh read = readGltf(glbOf(m, nullptr), "out.glb", "", true).mesh;
  for (std::size_t v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(read.positions[v][a], double(float(m.positions[v][a])));
}

// A UV triangle whose float32 (u, 1 - v) corners are collinear: far from [0, 1] (u = 1e15, where
// float32's step is 2^26), or finer than its step near v = 0 (1 - 1e-9 rounds to 1). A triangle
// already of zero area has nothing to lose.
TEST(GltfTexcoords, ATriangleCollapsesWhereFloat32LosesItsArea) {
  EXPECT_FALSE(collapsesInGltfTexcoords({0, 0}, {1, 0}, {0, 1}));
  EXPECT_TRUE(collapsesInGltfTexcoords({1e15, 0}, {1e15 + 1, 0}, {1e15, 1}));
  EXPECT_TRUE(collapsesInGltfTexcoords({0.5, 0}, {0.6, 0}, {0.5, 1e-9}));
  EXPECT_FALSE(collapsesInGltfTexcoords({0.5, 0}, {0.6, 0}, {0.7, 0}));
  EXPECT_FALSE(collapsesInGltfTexcoords({0.5, 0.5}, {0.6, 0.5}, {0.5, 0.5 + 1e-6}));  // float32 holds 1e-6 here
  EXPECT_EQ(gltfTexcoord(Vec2(0.25, 1e-9)), (std::array<float, 2>{0.25f, 1.0f}));
}

// A layout below float32's normal range (a two-plane map of a mesh 1e-150 across) would be written
// as zeros and ones: refused, nothing written.
TEST(WriteGltf, RefusesALayoutBelowFloat32sNormalRange) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1e-150, 0, 0}, {0, 1e-150, 0}};
  m.triangles = {{0, 1, 2}};
  UvMap uvs;
  uvs.uv = {{0, 0}, {1e-150, 0}, {0, 1e-150}};
  uvs.faceFlags = {kFaceOk};
  GltfWriteOptions options;
  options.name = "out.glb";
  std::ostringstream out;
  try {
    writeGlb(out, m, &uvs, options);
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_STREQ(e.what(), "out.glb: error: cannot write: the UVs (largest magnitude 1e-150) are below glTF's float32 "
                           "normal range (1.17549435e-38): the layout would be lost; scale them first");
  }
  EXPECT_TRUE(out.str().empty());
  for (Vec2& uv : uvs.uv) uv *= 1e150;  // the same layout at unit size: written, the positions at a power-of-two scale
  writeGlb(out, m, &uvs, options);
  EXPECT_FALSE(out.str().empty());
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
