// The public mesh: conversions, reading, checking and writing, and the command-line helpers the
// options' parse() functions share.
#include <cmath>
#include <string>

#include "detail.h"
#include "io/mesh_reader.h"
#include "io/mesh_writer.h"

namespace uvtk::api {

namespace {

template <class To, class From>
std::vector<To> convertPoints(const std::vector<From>& from) {
  std::vector<To> to(from.size());
  for (std::size_t i = 0; i < from.size(); ++i)
    for (int k = 0; k < 3; ++k) to[i][k] = from[i][k];
  return to;
}

// Throws std::invalid_argument unless every entry of `table` (empty, or one per triangle) is
// below `count` (and at least 0, or -1 where `optional`).
void checkIndices(const std::vector<Triangle>& table, std::size_t count, std::size_t triangles, const char* what,
                  bool optional) {
  if (optional && table.empty()) return;
  if (table.size() != triangles)
    throw std::invalid_argument(std::string("mesh: ") + what + " has " + std::to_string(table.size()) +
                                " entries, expected one per triangle (" + std::to_string(triangles) + ")");
  for (std::size_t f = 0; f < table.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int index = table[f][k];
      if ((optional && index == -1) || (index >= 0 && std::size_t(index) < count)) continue;
      throw std::invalid_argument(std::string("mesh: ") + what + " of triangle " + std::to_string(f) + ", corner " +
                                  std::to_string(k) + ": index " + std::to_string(index) + " is outside 0.." +
                                  std::to_string(count) + (count ? " - 1" : " (there are none)"));
    }
}

void checkFinite(const std::vector<Vector3>& points, const char* what) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(points[i][k]))
        throw std::invalid_argument(std::string("mesh: ") + what + " " + std::to_string(i) + " is not finite");
}

}  // namespace

InputError::~InputError() = default;
OutputError::~OutputError() = default;
ParameterTypeError::~ParameterTypeError() = default;

uvtk::Mesh toEngine(const Mesh& mesh) {
  uvtk::Mesh engine;
  engine.positions = convertPoints<Vec3>(mesh.positions);
  engine.triangles = mesh.triangles;
  engine.texcoords = convertPoints<Vec3>(mesh.texcoords);
  engine.cornerTexcoords = mesh.cornerTexcoords;
  engine.normals = convertPoints<Vec3>(mesh.normals);
  engine.cornerNormals = mesh.cornerNormals;
  engine.listedFaceFlags = mesh.faceFlags;
  return engine;
}

Mesh fromEngine(const uvtk::Mesh& engine) {
  Mesh mesh;
  mesh.positions = convertPoints<Vector3>(engine.positions);
  mesh.triangles = engine.triangles;
  mesh.texcoords = convertPoints<Vector3>(engine.texcoords);
  mesh.cornerTexcoords = engine.cornerTexcoords;
  mesh.normals = convertPoints<Vector3>(engine.normals);
  mesh.cornerNormals = engine.cornerNormals;
  mesh.faceFlags = engine.listedFaceFlags;
  return mesh;
}

MeshWarnings fromEngine(const uvtk::MeshWarnings& w) {
  return {w.degenerateFaces, w.unreferencedVertices, w.nonSimplePolygons,
          w.firstNonSimplePolygonLine, w.vertexColours, w.parameterVertices, w.weldedCorners, w.skippedPrimitives,
          w.listedInvalidUvFaces};
}

Mesh readMesh(const std::string& path, MeshWarnings* warnings, int threads) {
  if (threads < 0 || threads > 1024)
    throw std::invalid_argument("readMesh: threads: expected 0 to 1024, got " + std::to_string(threads));
  return translatingErrors([&] {
    io::ReadMeshResult read = io::readMesh(path, threads);
    if (warnings) *warnings = fromEngine(read.warnings);
    return fromEngine(read.mesh);
  });
}

// What checkMesh checks in the public mesh itself, before the engine sees it.
static void checkIndicesAndNumbers(const Mesh& mesh) {
  const std::size_t triangles = mesh.triangles.size();
  // As every reader refuses a file without faces: there is nothing to map, judge or write.
  if (triangles == 0) throw std::invalid_argument("mesh: expected at least one face, found none");
  checkFinite(mesh.positions, "position");
  checkFinite(mesh.texcoords, "texcoord");
  checkFinite(mesh.normals, "normal");
  checkIndices(mesh.triangles, mesh.positions.size(), triangles, "the position index", false);
  checkIndices(mesh.cornerTexcoords, mesh.texcoords.size(), triangles, "the texcoord index", true);
  checkIndices(mesh.cornerNormals, mesh.normals.size(), triangles, "the normal index", true);
  if (!mesh.faceFlags.empty() && mesh.faceFlags.size() != triangles)
    throw std::invalid_argument("mesh: expected one face flag per triangle (" + std::to_string(triangles) + ") or none, found " +
                                std::to_string(mesh.faceFlags.size()));
}

CheckedMesh checked(const Mesh& mesh) {
  checkIndicesAndNumbers(mesh);
  CheckedMesh out{toEngine(mesh), nullptr};
  const uvtk::MeshWarnings warnings = uvtk::checkMesh(out.engine);
  out.input = {{"vertices", out.engine.vertexCount()},
               {"faces", out.engine.faceCount()},
               {"degenerate_faces", warnings.degenerateFaces},
               {"unreferenced_vertices", warnings.unreferencedVertices},
               {"welded_corners", 0},  // what a reader did: nothing, for a mesh in memory
               {"skipped_primitives", 0},
               {"listed_invalid_uv_faces", 0}};
  return out;
}

MeshWarnings checkMesh(const Mesh& mesh) {
  checkIndicesAndNumbers(mesh);
  return fromEngine(uvtk::checkMesh(toEngine(mesh)));
}

void writeMesh(const std::string& path, const Mesh& mesh) {
  const uvtk::Mesh engine = checked(mesh).engine;
  translatingErrors([&] {
    UvMap uvs;
    if (engine.hasTexcoords()) uvs = inspect::fileUvs(engine, path);
    io::writeMesh(path, engine, engine.hasTexcoords() ? &uvs : nullptr);
  });
}

std::string version() { return UVTK_VERSION; }

std::vector<std::string> splitCommandLine(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool inWord = false;
  char quote = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quote) {
      if (c == quote) quote = 0;
      else if (c == '\\' && quote == '"' && i + 1 < text.size()) word += text[++i];
      else word += c;
    } else if (c == '\'' || c == '"') {
      quote = c, inWord = true;
    } else if (c == '\\' && i + 1 < text.size()) {
      word += text[++i], inWord = true;
    } else if (c == ' ' || c == '\t' || c == '\n') {
      if (inWord) words.push_back(word), word.clear(), inWord = false;
    } else {
      word += c, inWord = true;
    }
  }
  if (quote) throw UsageError(std::string("unterminated ") + quote + " in: " + text);
  if (inWord) words.push_back(word);
  return words;
}

std::string joinCommandLine(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) {
    if (!line.empty()) line += ' ';
    const bool plain = !word.empty() && word.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") == std::string::npos;
    if (plain) {
      line += word;
    } else {
      line += '\'';
      for (const char c : word) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
      line += '\'';
    }
  }
  return line;
}

}  // namespace uvtk::api
