// A scene file (schema/scene.schema.json): meshes with their mappings, cameras, textures and the
// outputs to write, read and checked completely before any work starts. A projector mapping's keys
// are typed parameters read by param::makeProjector, as the command line's options are (key
// "axis_dir" is --axis-dir), and so are the other objects' (read by the readers the subcommands they
// mirror use), so a scene can say exactly what the command line can, checked the same way.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "inspect/compare.h"
#include "core/math.h"
#include "timing/bench.h"
#include "io/mesh_writer.h"
#include "param/projector.h"
#include "inspect/render_parameters.h"
#include "inspect/report.h"
#include "texgen/texgen.h"

namespace uvtk::scene {

// The scene schema, as shipped in schema/scene.schema.json (embedded at build time).
const char* sceneSchemaText();

struct SceneMesh {
  std::string name, path, pointer;  // path resolved against the scene's folder; pointer: JSON Pointer
  Mat4 model = Mat4::Identity();
};

struct SceneMapping {
  enum class Kind { Projector, Texgen, File };
  std::string name, pointer;
  std::size_t mesh = 0;
  Kind kind = Kind::File;
  param::ProjectorOptions projector;
  bool seamPlaceAuto = false;
  texgen::TexgenOptions texgen;       // under the identity: drawnUnder the view and the model when it runs
  std::optional<std::size_t> camera;  // texgen: the view of this camera, else viewFromWorld
  Mat4 viewFromWorld = Mat4::Identity();

  // Whether computing the mapping reads vertex normals (an O-mapping or texgen mode that needs them).
  bool needsNormals() const;
};

struct SceneCamera {
  std::string name, pointer;
  inspect::CameraSettings settings;
};

struct SceneTexture {
  std::string name, pointer;
  inspect::TextureSettings settings;  // its files resolved against the scene's folder
};

struct SceneOutput {
  enum class Kind { Mesh, Render, Report, Compare, Gallery, Bench };
  Kind kind = Kind::Mesh;
  std::string pointer;
  std::optional<std::size_t> mapping, mesh, camera, texture;
  std::string path, json;     // mesh, render, gallery: the file; mesh, render: the summary JSON
  io::MeshWriteOptions write;  // mesh (the header is set when written)
  inspect::FrameSettings frame;                   // render
  inspect::ReportOptions report;                  // report
  inspect::CompareOptions compare;                // compare (the scene's thresholds are set when it runs)
  timing::BenchOptions bench;                    // bench: `uvtk bench` of the mesh, html = path
  std::string title;                         // gallery

  std::vector<std::string> files() const;  // every file it writes
};

struct Scene {
  std::string path, title;
  std::vector<SceneMesh> meshes;
  std::vector<SceneMapping> mappings;
  std::vector<SceneCamera> cameras;
  std::vector<SceneTexture> textures;
  std::vector<SceneOutput> outputs;
  analysis::Thresholds thresholds;  // the verdict's, for every mapping ("thresholds")
  inspect::TextureSettings defaultTexture;  // for render outputs that name none
};

// Reads and checks the scene at `path`: against the schema, then names and references, input
// files, and every option as its subcommand checks it. Output paths are taken relative to
// `outputDir` (empty: the scene's folder) and checked by checkOutputPath. Throws InputError
// "SCENE: /json/pointer: problem".
Scene loadScene(const std::string& path, const std::string& outputDir, bool allowOutside = false);

// The file an output path of a scene names: `path` relative to `outputDir`, lexically normalised.
// Refuses (InputError with the problem, naming `path` as quotedName()) what no file system can hold or
// what is not a file: an empty path, a NUL byte, a component longer than NAME_MAX (255 bytes), a
// result longer than PATH_MAX - 1, a folder ("." or ".." last, a trailing "/", an existing folder);
// and, unless `allowOutside`, a path that leaves `outputDir`: absolute, through "..", or through a
// symbolic link to a folder outside it (weakly_canonical at check time; the last component may be
// a link, which the atomic rename replaces rather than follows).
std::string checkOutputPath(const std::string& path, const std::filesystem::path& outputDir, bool allowOutside);

}  // namespace uvtk::scene
