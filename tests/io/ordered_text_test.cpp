// Text formatted on several threads and written in order (io/ordered_text.h), and the OBJ writer and
// vertex splitting built on it: the bytes and numbers of the sequential code they replace, on any
// number of threads.
#include "io/ordered_text.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/obj_writer.h"
#include "io/split_vertices.h"
#include "meshes/generators.h"
#include "doubles.h"

namespace uvtk::io {
namespace {
namespace UVTK_TEST_FILE {

TEST(OrderedText, WritesTheBlocksInOrderWhateverThreadMadeThem) {
  for (const int threads : {1, 2, 3, 8}) {
    std::ostringstream out;
    OrderedText text(out, threads);
    text.text("head;");
    // Blocks of very different sizes, so that threads finish out of order.
    text.blocks(1000, [](std::size_t i, TextBlock& block) {
      const std::string s = std::to_string(i) + std::string(i % 97 == 0 ? 100000 : i % 7, '.') + ";";
      char* p = block.room(s.size());
      std::memcpy(p, s.data(), s.size());
      block.commit(p + s.size());
    });
    text.text("tail");
    std::string expected = "head;";
    for (std::size_t i = 0; i < 1000; ++i) expected += std::to_string(i) + std::string(i % 97 == 0 ? 100000 : i % 7, '.') + ";";
    EXPECT_EQ(out.str(), expected + "tail") << threads;
  }
}

// ---------------------------------------------------------------------------------------------
// The sequential vertex splitting and OBJ writer as they were before they ran on several threads,
// kept here as the reference for every byte.

SplitVertices referenceSplit(const Mesh& mesh, const SplitVertexKey& key) {
  const std::size_t corners = 3 * mesh.triangles.size();
  const UvMap* uvs = key.uvs;
  const bool useW = key.w && uvs && !uvs->w.empty();
  const bool useNormals = key.normals && mesh.hasNormals();
  const auto vertexOf = [&](std::size_t c) { return mesh.triangles[c / 3][c % 3]; };
  const auto sameKey = [&](std::size_t a, std::size_t b) {
    if (uvs && !(sameBits(uvs->writtenUv(a).x(), uvs->writtenUv(b).x()) &&
                 sameBits(uvs->writtenUv(a).y(), uvs->writtenUv(b).y())))
      return false;
    if (useW && !sameBits(uvs->w[a], uvs->w[b])) return false;
    return !useNormals || mesh.cornerNormals[a / 3][a % 3] == mesh.cornerNormals[b / 3][b % 3];
  };
  const std::size_t vertexCount = mesh.positions.size();
  std::vector<std::size_t> firstOfVertex(vertexCount + 1, 0), byVertex(corners);
  for (std::size_t c = 0; c < corners; ++c) ++firstOfVertex[vertexOf(c) + 1];
  for (std::size_t v = 0; v < vertexCount; ++v) firstOfVertex[v + 1] += firstOfVertex[v];
  std::vector<std::size_t> next(firstOfVertex.begin(), firstOfVertex.end() - 1);
  for (std::size_t c = 0; c < corners; ++c) byVertex[next[vertexOf(c)]++] = c;
  SplitVertices split;
  split.ofCorner.resize(corners);
  for (std::size_t v = 0; v < vertexCount; ++v) {
    const std::size_t begin = firstOfVertex[v], end = firstOfVertex[v + 1];
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t c = byVertex[i];
      std::size_t same = begin;
      while (same < i && !sameKey(byVertex[same], c)) ++same;
      if (same < i) {
        split.ofCorner[c] = split.ofCorner[byVertex[same]];
        continue;
      }
      split.ofCorner[c] = static_cast<int>(split.vertex.size());
      split.vertex.push_back(static_cast<int>(v));
      split.corner.push_back(c);
    }
  }
  return split;
}

std::string referenceObj(const Mesh& mesh, const UvMap* uvs, const ObjWriteOptions& options) {
  std::string out;
  const auto number = [&](double value, bool asFloat) {
    char digits[32];
    const std::to_chars_result r = asFloat ? std::to_chars(digits, digits + 32, static_cast<float>(value))
                                           : std::to_chars(digits, digits + 32, value);
    out.append(digits, r.ptr);
  };
  const auto vectorLine = [&](const char* keyword, const Vec3& p) {
    out += keyword;
    for (int a = 0; a < 3; ++a) {
      if (a > 0) out += ' ';
      number(p[a], false);
    }
    out += '\n';
  };
  std::istringstream lines(options.header);
  for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
  for (const Vec3& p : mesh.positions) vectorLine("v ", p);
  std::vector<int> cornerTexcoord;
  if (uvs) {
    const bool hasW = options.writeW && !uvs->w.empty();
    SplitVertices split = referenceSplit(mesh, {uvs, hasW, false});
    for (const std::size_t c : split.corner) {
      out += "vt ";
      number(uvs->writtenUv(c).x(), options.floatPrecision);
      out += ' ';
      number(uvs->writtenUv(c).y(), options.floatPrecision);
      if (options.writeW) {
        out += ' ';
        number(hasW ? uvs->w[c] : 0.0, options.floatPrecision);
      }
      out += '\n';
    }
    cornerTexcoord = std::move(split.ofCorner);
  }
  const bool normals = mesh.hasNormals();
  if (normals)
    for (const Vec3& n : mesh.normals) vectorLine("vn ", n);
  const std::size_t faceCount = mesh.triangles.size();
  if (uvs) {
    std::size_t invalid = 0;
    for (std::size_t f = 0; f < faceCount; ++f) invalid += uvs->faceHas(f, kFaceInvalid) ? 1 : 0;
    if (invalid > 0) {
      out += "# " + std::to_string(invalid) + " faces have corners without a valid UV (written as vt 0 0); 1-based face numbers:";
      // Each block of 8192 faces after the first that lists any goes on a line of its own.
      std::size_t lineBlock = faceCount;
      for (std::size_t f = 0; f < faceCount; ++f)
        if (uvs->faceHas(f, kFaceInvalid)) {
          if (lineBlock != faceCount && f / 8192 != lineBlock) out += "\n# more 1-based face numbers:";
          lineBlock = f / 8192;
          out += " " + std::to_string(f + 1);
        }
      out += '\n';
    }
  }
  for (std::size_t f = 0; f < faceCount; ++f) {
    const Triangle& t = mesh.triangles[f];
    const bool faceNormals =
        normals && mesh.cornerNormals[f][0] >= 0 && mesh.cornerNormals[f][1] >= 0 && mesh.cornerNormals[f][2] >= 0;
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ' + std::to_string(t[k] + 1);
      if (uvs || faceNormals) out += '/';
      if (uvs) out += std::to_string(cornerTexcoord[3 * f + k] + 1);
      if (faceNormals) out += '/' + std::to_string(mesh.cornerNormals[f][k] + 1);
    }
    out += '\n';
  }
  return out;
}

// A sphere of 160 x 120 (more lines than a block holds) with UVs that differ across a seam and at
// the poles, some -0 beside +0, a third component, invalid faces, and normals on some faces only.
struct Scene {
  Mesh mesh = meshes::latLongSphere(160, 120);
  UvMap uvs;
  Scene() {
    std::mt19937 random(5);
    const std::size_t corners = 3 * mesh.triangles.size();
    uvs.uv.resize(corners);
    uvs.w.resize(corners);
    uvs.cornerInvalid.assign(corners, 0);
    uvs.faceFlags.assign(mesh.triangles.size(), kFaceOk);
    for (std::size_t c = 0; c < corners; ++c) {
      const Vec3& p = mesh.positions[mesh.triangles[c / 3][c % 3]];
      double u = std::atan2(p.y(), p.x()) / (2 * M_PI) + 0.5;
      if (c % 3 == 0 && p.y() == 0.0) u = 1.0;  // a seam: the same vertex at u = 0 and u = 1
      uvs.uv[c] = Vec2(random() % 50 == 0 ? -0.0 : u, std::acos(std::clamp(p.z(), -1.0, 1.0)) / M_PI);
      uvs.w[c] = static_cast<double>(c % 6);
    }
    for (std::size_t f = 0; f < mesh.triangles.size(); f += 997) {  // one corner each, its stored UV not (0, 0)
      uvs.faceFlags[f] = kFaceInvalid;
      uvs.cornerInvalid[3 * f + f % 3] = kCornerMiss;
    }
    mesh.normals = {{0, 0, 1}, {1.0 / 3.0, 0.25, -1e-300}};
    mesh.cornerNormals.assign(mesh.triangles.size(), {-1, -1, -1});
    for (std::size_t f = 0; f < mesh.triangles.size(); f += 3) mesh.cornerNormals[f] = {0, 1, f % 2 == 0 ? 0 : -1};
  }
};

TEST(WriteObjThreads, TheBytesOfTheSequentialWriterForEveryOption) {
  const Scene scene;
  Mesh withoutNormals = scene.mesh;
  withoutNormals.normals.clear();
  withoutNormals.cornerNormals.clear();
  UvMap withoutW = scene.uvs;
  withoutW.w.clear();
  int cases = 0;
  for (const Mesh* mesh : std::vector<const Mesh*>{&scene.mesh, &withoutNormals})
    for (const UvMap* uvs : std::vector<const UvMap*>{&scene.uvs, &withoutW, nullptr})
      for (const bool asFloat : {false, true})
        for (const bool writeW : {false, true}) {
          ObjWriteOptions options;
          options.floatPrecision = asFloat;
          options.writeW = writeW;
          options.header = asFloat ? "one line" : "two\nlines";
          const std::string expected = referenceObj(*mesh, uvs, options);
          for (const int threads : {1, 2, 3}) {
            options.threads = threads;
            std::ostringstream out;
            writeObj(out, *mesh, uvs, options);
            ASSERT_EQ(out.str(), expected) << "case " << cases << ", " << threads << " threads";
          }
          ++cases;
        }
  EXPECT_EQ(cases, 24);
}

TEST(SplitVerticesThreads, TheSequentialSplitOnAnyNumberOfThreads) {
  const Scene scene;
  for (const SplitVertexKey key : {SplitVertexKey{&scene.uvs, false, false}, SplitVertexKey{&scene.uvs, true, false},
                                   SplitVertexKey{&scene.uvs, false, true}, SplitVertexKey{nullptr, false, true}}) {
    const SplitVertices expected = referenceSplit(scene.mesh, key);
    ASSERT_GT(expected.size(), scene.mesh.positions.size());  // split somewhere, or the test proves little
    for (const int threads : {1, 2, 3, 8}) {
      const SplitVertices split = splitVertices(scene.mesh, key, threads);
      EXPECT_EQ(split.vertex, expected.vertex) << threads;
      EXPECT_EQ(split.corner, expected.corner) << threads;
      EXPECT_EQ(split.ofCorner, expected.ofCorner) << threads;
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::io
