// glTF 2.0 writing: one buffer (positions, normals, UVs, indices, each bufferView tightly packed
// and 4-byte aligned), one mesh of one indexed triangle primitive, one node, one scene.
//
// The JSON is made here with nlohmann::json rather than by tinygltf's writer: that one writes an
// external .bin itself, by path, where our outputs are staged and published together (OutputSet),
// and it embeds every buffer as a data URI whenever it writes to a stream.
//
// Decisions:
// - Vertices are split where corners disagree on the UV or the normal (io/split_vertices.h), so
//   seams survive; a vertex no face uses is not written.
// - NORMAL, when the mesh has normals or the caller gives vertex normals: unit float32. A corner
//   without a normal (or with a zero one) gets the area-weighted vertex normal; a vertex whose
//   faces all have zero area gets +z, since a zero normal is invalid glTF and no visible face
//   shades with it.
// - TEXCOORD_0 is (u, 1 - v): glTF's v runs down the image. A face with an invalid corner is listed
//   in the mesh's extras ({"uvtk": {"invalid_faces": [...]}}, 0-based); its invalid corners hold
//   the UvMap's (0, 0), written (0, 1).
// - Indices are UNSIGNED_SHORT up to 65535 vertices (the largest index then is 65534: 65535 is the
//   primitive restart value glTF forbids), UNSIGNED_INT beyond.
// - min and max of POSITION and TEXCOORD_0 are those of the float32 values written, as the
//   validator recomputes them.
// - A mesh far from the origin (its bounding box's centre farther, in its largest coordinate, than
//   1.5 times the box's largest side) is written relative to that centre, which becomes the node's
//   translation (a JSON double): float32 then spends its digits on the shape, not on the distance,
//   as CesiumJS's relative-to-centre and 3D Tiles do. A reader composes the node's transform in
//   double and gets the positions back to float32's precision at the mesh's size.
// - A mesh whose coordinates (relative to that centre) reach 2^63 or stay below 2^-62 is written
//   divided by a power of two, the node's uniform scale, so that they lie in (-2, 2): float32's
//   range (about 1.2e-38 to 3.4e38) holds any double mesh, and squared lengths, which renderers
//   compute in float32, stay in it too. The division is exact.
// - Degenerate and non-manifold triangles are written as they are.
#include "io/gltf_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/face_lists.h"
#include "io/split_vertices.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "glTF buffers are little-endian; written with memcpy");

namespace uvtk::io {
namespace {

using nlohmann::json;

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr std::size_t kMaxShortVertices = 65535;

struct GltfParts {
  json document;    // without the buffer's uri
  std::string bin;  // the buffer's bytes, unpadded
};

void putFloat(std::string& out, float value) {
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.append(bytes, 4);
}

// The shortest text that reads back as `value`.
std::string numberText(double value) { return json(value).dump(); }

Vec3 unitOrZero(const Vec3& v) {
  const double length = v.stableNorm();
  return length > 0.0 && std::isfinite(length) ? Vec3(v / length) : Vec3::Zero();
}

// Appends one accessor of float VECn over `values` (n per element) and its bufferView.
void addFloatAccessor(GltfParts& parts, const std::vector<float>& values, int n, bool withBounds) {
  const std::size_t count = values.size() / static_cast<std::size_t>(n);
  const std::size_t offset = parts.bin.size();
  for (const float f : values) putFloat(parts.bin, f);
  json& views = parts.document["bufferViews"];
  views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", parts.bin.size() - offset}, {"target", kArrayBuffer}});
  json accessor = {{"bufferView", views.size() - 1}, {"componentType", kFloat}, {"count", count}, {"type", n == 2 ? "VEC2" : "VEC3"}};
  if (withBounds) {
    std::vector<float> low(static_cast<std::size_t>(n), std::numeric_limits<float>::infinity());
    std::vector<float> high(static_cast<std::size_t>(n), -std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      low[i % static_cast<std::size_t>(n)] = std::min(low[i % static_cast<std::size_t>(n)], values[i]);
      high[i % static_cast<std::size_t>(n)] = std::max(high[i % static_cast<std::size_t>(n)], values[i]);
    }
    accessor["min"] = json::array();
    accessor["max"] = json::array();
    for (int a = 0; a < n; ++a) {
      accessor["min"].push_back(static_cast<double>(low[static_cast<std::size_t>(a)]));
      accessor["max"].push_back(static_cast<double>(high[static_cast<std::size_t>(a)]));
    }
  }
  parts.document["accessors"].push_back(std::move(accessor));
}

// Where the written positions sit: p = origin + 2^exponent q, q the float32 values in the buffer
// (the node's translation and scale; see the decisions above).
struct PositionFrame {
  Vec3 origin = Vec3::Zero();
  int exponent = 0;
  bool moved() const { return !origin.isZero(0.0); }
};

// Coordinates of magnitude in [2^-62, 2^63) are written unscaled: their squares, as renderers
// compute lengths in float32, stay in its normal range.
constexpr int kLargestUnscaledExponent = 62;

PositionFrame positionFrame(const Mesh& mesh, const std::vector<int>& vertices) {
  PositionFrame frame;
  Eigen::AlignedBox3d box;
  for (const int v : vertices) box.extend(mesh.positions[static_cast<std::size_t>(v)]);
  if (box.isEmpty()) return frame;
  const Vec3 centre = 0.5 * box.min() + 0.5 * box.max();  // halves first: the sum could overflow
  const double side = (box.max() - box.min()).maxCoeff();  // inf when the box spans the doubles: not moved
  if (centre.cwiseAbs().maxCoeff() > 1.5 * side) frame.origin = centre;
  double largest = 0.0;
  for (const int v : vertices) largest = std::max(largest, (mesh.positions[static_cast<std::size_t>(v)] - frame.origin).cwiseAbs().maxCoeff());
  if (largest > 0.0 && std::isfinite(largest) && std::abs(std::ilogb(largest)) > kLargestUnscaledExponent)
    frame.exponent = std::ilogb(largest);
  return frame;
}

GltfParts buildGltf(const Mesh& mesh, const UvMap* uvs, const GltfWriteOptions& options) {
  const std::size_t faceCount = mesh.triangles.size();
  UVTK_CHECK(!uvs || uvs->uv.size() == 3 * faceCount);
  UVTK_CHECK(!options.vertexNormals || options.vertexNormals->size() == mesh.positions.size());
  const std::string cannot = options.name + ": error: cannot write: ";
  if (faceCount == 0) throw OutputError(cannot + "a glTF primitive needs at least one triangle, the mesh has none");

  const SplitVertices split = splitVertices(mesh, {uvs, false, true});
  const std::size_t n = split.size();
  const PositionFrame frame = positionFrame(mesh, split.vertex);
  // Everything is converted, and checked against float32's range, before a byte is written.
  std::vector<float> positions(3 * n), texcoords(uvs ? 2 * n : 0);
  double largestUv = 0.0;
  for (std::size_t s = 0; s < n; ++s) {
    const Vec3& p = mesh.positions[static_cast<std::size_t>(split.vertex[s])];
    for (int a = 0; a < 3; ++a) {
      const float f = static_cast<float>(std::ldexp(p[a] - frame.origin[a], -frame.exponent));
      if (!std::isfinite(f))
        throw OutputError(cannot + "vertex " + std::to_string(split.vertex[s]) + " at (" + numberText(p.x()) + ", " +
                          numberText(p.y()) + ", " + numberText(p.z()) +
                          ") is beyond glTF's float32 range (magnitude at most 3.40282347e+38)");
      positions[3 * s + static_cast<std::size_t>(a)] = f;
    }
    if (uvs) {
      const std::size_t c = split.corner[s];
      const Vec2 uv = uvs->writtenUv(c);
      const auto [u, v] = gltfTexcoord(uv);
      if (!std::isfinite(u) || !std::isfinite(v))
        throw OutputError(cannot + "the UV (" + numberText(uv.x()) + ", " + numberText(uv.y()) + ") of face " + std::to_string(c / 3) +
                          " corner " + std::to_string(c % 3) + " is beyond glTF's float32 range (magnitude at most 3.40282347e+38)");
      texcoords[2 * s] = u;
      texcoords[2 * s + 1] = v;
      largestUv = std::max({largestUv, std::fabs(uv.x()), std::fabs(uv.y())});
    }
  }
  // UVs can be placed by no transform: a layout below float32's normal range (a two-plane map of a
  // mesh 1e-150 across, in object units) would reach the file as zeros and subnormals.
  if (largestUv > 0.0 && largestUv < double(std::numeric_limits<float>::min()))
    throw OutputError(cannot + "the UVs (largest magnitude " + numberText(largestUv) +
                      ") are below glTF's float32 normal range (1.17549435e-38): the layout would be lost; scale "
                      "them first");
  GltfParts parts;
  json& document = parts.document;
  document["asset"] = {{"version", "2.0"}};
  if (!options.generator.empty()) document["asset"]["generator"] = options.generator;
  if (!options.copyright.empty()) document["asset"]["copyright"] = options.copyright;
  document["scene"] = 0;
  document["scenes"] = json::array({{{"nodes", {0}}}});
  json node = {{"mesh", 0}};
  if (frame.moved()) node["translation"] = {frame.origin.x(), frame.origin.y(), frame.origin.z()};
  if (frame.exponent != 0) {
    const double scale = std::ldexp(1.0, frame.exponent);
    node["scale"] = {scale, scale, scale};
  }
  document["nodes"] = json::array({std::move(node)});
  document["bufferViews"] = json::array();
  document["accessors"] = json::array();
  json primitive = {{"attributes", json::object()}};

  addFloatAccessor(parts, positions, 3, true);
  primitive["attributes"]["POSITION"] = 0;

  if (mesh.hasNormals() || options.vertexNormals) {
    std::vector<Vec3> vertexNormals;  // for corners without a normal of their own
    if (mesh.hasNormals()) vertexNormals = areaWeightedVertexNormals(mesh);
    std::vector<float> normals(3 * n);
    for (std::size_t s = 0; s < n; ++s) {
      const std::size_t c = split.corner[s], v = static_cast<std::size_t>(split.vertex[s]);
      Vec3 normal = Vec3::Zero();
      if (mesh.hasNormals()) {
        const int index = mesh.cornerNormals[c / 3][c % 3];
        if (index >= 0) normal = unitOrZero(mesh.normals[static_cast<std::size_t>(index)]);
        if (normal.isZero(0.0)) normal = unitOrZero(vertexNormals[v]);
      } else {
        normal = unitOrZero((*options.vertexNormals)[v]);
      }
      if (normal.isZero(0.0)) normal = Vec3::UnitZ();
      for (int a = 0; a < 3; ++a) normals[3 * s + static_cast<std::size_t>(a)] = static_cast<float>(normal[a]);
    }
    addFloatAccessor(parts, normals, 3, false);
    primitive["attributes"]["NORMAL"] = document["accessors"].size() - 1;
  }

  if (uvs) {
    addFloatAccessor(parts, texcoords, 2, true);
    primitive["attributes"]["TEXCOORD_0"] = document["accessors"].size() - 1;
  }

  // Indices last: UNSIGNED_SHORT ones may end off a 4-byte boundary, and nothing follows them.
  const bool shortIndices = n <= kMaxShortVertices;
  const std::size_t offset = parts.bin.size();
  for (const int s : split.ofCorner) {
    const std::uint32_t index = static_cast<std::uint32_t>(s);
    if (shortIndices) {
      const std::uint16_t small = static_cast<std::uint16_t>(index);
      parts.bin.append(reinterpret_cast<const char*>(&small), 2);
    } else {
      parts.bin.append(reinterpret_cast<const char*>(&index), 4);
    }
  }
  document["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", parts.bin.size() - offset}, {"target", kElementArrayBuffer}});
  document["accessors"].push_back({{"bufferView", document["bufferViews"].size() - 1},
                                   {"componentType", shortIndices ? kUnsignedShort : kUnsignedInt},
                                   {"count", split.ofCorner.size()},
                                   {"type", "SCALAR"}});
  primitive["indices"] = document["accessors"].size() - 1;

  json gltfMesh = {{"primitives", json::array({primitive})}};
  for (const FaceList& list : kFaceLists) {
    const std::vector<std::size_t> listed = facesWith(uvs, list.flag);
    if (!listed.empty()) gltfMesh["extras"]["uvtk"][std::string(list.gltfKey)] = listed;
  }
  document["meshes"] = json::array({std::move(gltfMesh)});
  document["buffers"] = json::array({{{"byteLength", parts.bin.size()}}});
  return parts;
}

void putU32(std::ostream& out, std::uint32_t value) {
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.write(bytes, 4);
}

// A file name as a relative URI reference: every byte but RFC 3986's unreserved characters and
// '/' percent-encoded (a reader decodes "%20", and some "+", back).
std::string uriOf(const std::string& file) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string uri;
  for (const char c : file) {
    const unsigned char b = static_cast<unsigned char>(c);
    if (std::isalnum(b) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
      uri += c;
    } else {
      uri += '%';
      uri += kHex[b >> 4];
      uri += kHex[b & 15];
    }
  }
  return uri;
}

}  // namespace

std::array<float, 2> gltfTexcoord(const Vec2& uv) { return {static_cast<float>(uv.x()), static_cast<float>(1.0 - uv.y())}; }

bool collapsesInGltfTexcoords(const Vec2& a, const Vec2& b, const Vec2& c) {
  const auto twiceArea = [](const Vec2& p, const Vec2& q, const Vec2& r) {  // signed, in double
    return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
  };
  const auto stored = [](const Vec2& uv) {
    const auto [u, v] = gltfTexcoord(uv);
    return Vec2(u, v);
  };
  return twiceArea(a, b, c) != 0.0 && twiceArea(stored(a), stored(b), stored(c)) == 0.0;
}

void writeGlb(std::ostream& out, const Mesh& mesh, const UvMap* uvs, const GltfWriteOptions& options) {
  GltfParts parts = buildGltf(mesh, uvs, options);
  std::string text = parts.document.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::string& bin = parts.bin;
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  const std::uint64_t length = 12 + 8 + text.size() + 8 + bin.size();
  if (length > UINT32_MAX)
    throw OutputError(options.name + ": error: cannot write: a GLB holds at most 4 GiB, this one would take " + std::to_string(length) + " bytes");
  out.write("glTF", 4);
  putU32(out, 2);
  putU32(out, static_cast<std::uint32_t>(length));
  putU32(out, static_cast<std::uint32_t>(text.size()));
  out.write("JSON", 4);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  putU32(out, static_cast<std::uint32_t>(bin.size()));
  out.write("BIN\0", 4);
  out.write(bin.data(), static_cast<std::streamsize>(bin.size()));
}

void writeGltf(std::ostream& jsonOut, std::ostream& binary, const std::string& binaryUri, const Mesh& mesh, const UvMap* uvs,
               const GltfWriteOptions& options) {
  GltfParts parts = buildGltf(mesh, uvs, options);
  parts.document["buffers"][0]["uri"] = uriOf(binaryUri);
  const std::string text = parts.document.dump(2) + "\n";
  jsonOut.write(text.data(), static_cast<std::streamsize>(text.size()));
  binary.write(parts.bin.data(), static_cast<std::streamsize>(parts.bin.size()));
}

}  // namespace uvtk::io
