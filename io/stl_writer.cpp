#include "io/stl_writer.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "core/error.h"

namespace uvtk::io {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;
constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

using Float3 = std::array<float, 3>;

Float3 toFloat(const Vec3& p) { return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())}; }

// The unit normal of the triangle as the file holds it (float corners, computed in double), or
// zero when it has no area.
Float3 unitNormal(const Float3& a, const Float3& b, const Float3& c) {
  const auto d = [](const Float3& p) { return Vec3(p[0], p[1], p[2]); };
  const Vec3 n = triangleAreaNormal(d(a), d(b), d(c));
  const double length = n.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};
  return toFloat(n / length);
}

// Every corner's position must survive the cast to float; checked before anything is written.
void checkFloatRange(const Mesh& mesh, const std::string& name) {
  for (const Triangle& t : mesh.triangles)
    for (const int v : t) {
      const Float3 p = toFloat(mesh.positions[static_cast<std::size_t>(v)]);
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) continue;
      std::string at;
      for (int a = 0; a < 3; ++a) {
        char digits[32];
        const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, mesh.positions[static_cast<std::size_t>(v)][a]);
        at += (a > 0 ? ", " : "") + std::string(digits, r.ptr);
      }
      throw OutputError(name + ": error: cannot write: vertex " + std::to_string(v) + " at (" + at +
                        ") is beyond the float32 range of STL (magnitude at most 3.40282347e+38)");
    }
}

void putFloat(char*& p, float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  for (int i = 0; i < 4; ++i) *p++ = static_cast<char>((bits >> (8 * i)) & 0xFF);  // little-endian
}

void writeBinary(std::ostream& out, const Mesh& mesh, const StlWriteOptions& options) {
  std::string header = "uvtk";
  if (!options.header.empty()) header += " " + options.header;
  header.resize(kHeaderBytes, '\0');
  const std::uint64_t count = mesh.triangles.size();
  UVTK_CHECK(count <= UINT32_MAX);
  for (int i = 0; i < 4; ++i) header.push_back(static_cast<char>((count >> (8 * i)) & 0xFF));
  out.write(header.data(), static_cast<std::streamsize>(header.size()));

  std::vector<char> buffer;
  buffer.reserve(kFlushBytes + kTriangleBytes);
  for (const Triangle& t : mesh.triangles) {
    const std::size_t at = buffer.size();
    buffer.resize(at + kTriangleBytes);
    char* p = buffer.data() + at;
    const Float3 corners[3] = {toFloat(mesh.positions[static_cast<std::size_t>(t[0])]),
                               toFloat(mesh.positions[static_cast<std::size_t>(t[1])]),
                               toFloat(mesh.positions[static_cast<std::size_t>(t[2])])};
    for (const float f : unitNormal(corners[0], corners[1], corners[2])) putFloat(p, f);
    for (const Float3& c : corners)
      for (const float f : c) putFloat(p, f);
    *p++ = 0;  // attribute byte count
    *p++ = 0;
    if (buffer.size() >= kFlushBytes) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

void appendFloats(std::string& text, const Float3& v) {
  for (const float f : v) {
    char digits[32];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, f);
    UVTK_CHECK(r.ec == std::errc());
    text.push_back(' ');
    text.append(digits, r.ptr);
  }
  text.push_back('\n');
}

void writeAscii(std::ostream& out, const Mesh& mesh, const StlWriteOptions& options) {
  std::string name = "uvtk";
  if (!options.header.empty()) name += " " + options.header;
  std::replace_if(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; }, ' ');
  std::string text = "solid " + name + "\n";
  for (const Triangle& t : mesh.triangles) {
    const Float3 corners[3] = {toFloat(mesh.positions[static_cast<std::size_t>(t[0])]),
                               toFloat(mesh.positions[static_cast<std::size_t>(t[1])]),
                               toFloat(mesh.positions[static_cast<std::size_t>(t[2])])};
    text += "  facet normal";
    appendFloats(text, unitNormal(corners[0], corners[1], corners[2]));
    text += "    outer loop\n";
    for (const Float3& c : corners) {
      text += "      vertex";
      appendFloats(text, c);
    }
    text += "    endloop\n  endfacet\n";
    if (text.size() >= kFlushBytes) {
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      text.clear();
    }
  }
  text += "endsolid " + name + "\n";
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

void writeStl(std::ostream& out, const Mesh& mesh, const StlWriteOptions& options) {
  checkFloatRange(mesh, options.name);
  if (options.ascii)
    writeAscii(out, mesh, options);
  else
    writeBinary(out, mesh, options);
}

}  // namespace uvtk::io
