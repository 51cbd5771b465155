#include "scene/scene.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "core/error.h"
#include "io/json_file.h"
#include "io/json_schema.h"
#include "io/mesh_format.h"
#include "io/mesh_writer.h"
#include "inspect/mapping_parameters.h"
#include "param/make_projector.h"
#include "param/surface_traits.h"
#include "timing/bench.h"
#include "render/procedural.h"

namespace uvtk::scene {

using namespace uvtk::inspect;
using namespace uvtk::timing;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// "--axis-dir" in a message becomes the scene's key "axis_dir".
std::string keysForOptions(const std::string& message) {
  std::string out;
  for (std::size_t i = 0; i < message.size();) {
    if (message.compare(i, 2, "--") == 0 && i + 2 < message.size() &&
        std::islower(static_cast<unsigned char>(message[i + 2]))) {
      i += 2;
      while (i < message.size() && (std::isalnum(static_cast<unsigned char>(message[i])) || message[i] == '-'))
        out += message[i] == '-' ? '_' : message[i], ++i;
    } else {
      out += message[i++];
    }
  }
  return out;
}

// `path` without a trailing separator ("a/b/" is "a/b"), so that its components compare.
fs::path withoutTrailingSlash(const fs::path& path) {
  return path.has_relative_path() && !path.has_filename() ? path.parent_path() : path;
}

// Whether `path` is `folder` or lies in it, component by component (both absolute or both not).
bool within(const fs::path& path, const fs::path& folder) {
  const fs::path p = withoutTrailingSlash(path.lexically_normal()), f = withoutTrailingSlash(folder.lexically_normal());
  if (f == ".") return p.is_relative() && (p.empty() || *p.begin() != "..");
  return std::mismatch(f.begin(), f.end(), p.begin(), p.end()).first == f.end();
}

class SceneReader {
 public:
  SceneReader(std::string path, const std::string& outputDir, bool allowOutside)
      : path_(std::move(path)),
        inputDir_(fs::path(path_).parent_path()),
        outputDir_(outputDir.empty() ? inputDir_ : fs::path(outputDir)),
        allowOutside_(allowOutside) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
    throw InputError(path_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + message);
  }

  // Runs `check`, reporting a UsageError from the option code at `pointer`, in the scene's names.
  template <class F>
  auto at(const std::string& pointer, F&& check) const {
    try {
      return check();
    } catch (const UsageError& e) {
      fail(pointer, keysForOptions(e.what()));
    }
  }

  // The keys of `object` (but `sceneKeys`) as typed parameters: key "axis_dir" is the parameter
  // axis-dir, named "axis_dir" in messages. The schema has checked the keys and their types.
  param::ParameterDictionary sceneParameters(const json& object, const std::set<std::string>& sceneKeys,
                                             const std::string& pointer) const {
    param::ParameterDictionary parameters(param::ParameterFace::Scene);
    for (const auto& [key, value] : object.items()) {
      if (sceneKeys.count(key)) continue;
      std::string name = key;
      std::replace(name.begin(), name.end(), '_', '-');
      param::ParameterValue typed;
      if (value.is_boolean()) typed = value.get<bool>();
      else if (value.is_number_integer()) typed = value.get<std::int64_t>();
      else if (value.is_number()) typed = value.get<double>();
      else if (value.is_string()) typed = value.get<std::string>();
      else if (value.is_array() && !value.empty() && value[0].is_string()) typed = value.get<std::vector<std::string>>();
      else if (value.is_array()) typed = value.get<std::vector<double>>();
      else if (!value.is_null()) fail(pointer + "/" + key, "expected a boolean, a number, a text or a list");
      parameters.add(name, std::move(typed), key);
    }
    return parameters;
  }

  // Inputs may be anywhere; a NUL would make the system read the file named by the part before it.
  std::string input(const json& value, const std::string& pointer) const {
    const std::string name = value.get<std::string>();
    if (name.find('\0') != std::string::npos) fail(pointer, quotedName(name) + ": a file name cannot hold a NUL byte");
    const fs::path file = inputDir_ / name;
    std::error_code error;
    if (fs::is_directory(file, error)) fail(pointer, quotedName(file.string()) + " is a folder, not a file");
    if (!fs::is_regular_file(file, error)) fail(pointer, "no such file " + quotedName(file.string()));
    return file.lexically_normal().string();
  }
  // An output file given at `pointer` (empty: none), as checkOutputPath resolves it.
  std::string output(const std::string& path, const std::string& pointer) const {
    if (path.empty()) return path;
    try {
      return checkOutputPath(path, outputDir_, allowOutside_);
    } catch (const InputError& e) {
      fail(pointer, e.what());
    }
  }

  // The index of the entry named `name` among `entries`, or an error listing the names there are.
  template <class Entry>
  std::size_t find(const std::vector<Entry>& entries, const json& name, const char* what,
                   const std::string& pointer) const {
    std::string known;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (entries[i].name == name.get<std::string>()) return i;
      known += (known.empty() ? "" : ", ") + entries[i].name;
    }
    fail(pointer, std::string("no ") + what + " named " + name.dump() +
                      (known.empty() ? "; the scene defines none" : "; the scene has: " + known));
  }

  template <class Entry>
  void checkUnique(const std::vector<Entry>& entries, const char* what) const {
    for (std::size_t i = 0; i < entries.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (entries[i].name == entries[j].name)
          fail(entries[i].pointer + "/name", std::string("duplicate ") + what + " name \"" + entries[i].name +
                                                 "\" (also at " + entries[j].pointer + ")");
  }

  // The schema has checked the names and the values' types.
  analysis::Thresholds thresholds(const json& j) const {
    analysis::Thresholds t;
    for (const auto severity : {analysis::Verdict::Warn, analysis::Verdict::Fail}) {
      const char* key = analysis::toString(severity);
      for (const auto& [rule, value] : j.value(key, json::object()).items()) {
        const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
        t.set(rule + "=" + text, severity, path_ + ": /thresholds/" + key + "/" + rule);
      }
    }
    return t;
  }

  Scene read() const {
    const json doc = io::readJsonFile(path_);
    static const json schema = json::parse(sceneSchemaText());
    const std::vector<io::SchemaError> errors = io::validateJson(doc, schema);
    if (!errors.empty()) {
      std::string message;
      for (const io::SchemaError& e : errors) message += (message.empty() ? "" : "\n" + path_ + ": ") + io::toString(e);
      throw InputError(path_ + ": " + message);
    }
    Scene scene;
    scene.path = path_;
    scene.title = doc.value("title", fs::path(path_).stem().string());
    if (doc.contains("thresholds")) scene.thresholds = thresholds(doc["thresholds"]);
    const json none = json::array();
    for (std::size_t i = 0; i < doc.value("cameras", none).size(); ++i)
      scene.cameras.push_back(camera(doc["cameras"][i], "/cameras/" + std::to_string(i)));
    checkUnique(scene.cameras, "camera");
    for (std::size_t i = 0; i < doc.value("textures", none).size(); ++i)
      scene.textures.push_back(texture(doc["textures"][i], "/textures/" + std::to_string(i)));
    checkUnique(scene.textures, "texture");
    for (std::size_t i = 0; i < doc["meshes"].size(); ++i) mesh(doc["meshes"][i], i, scene);
    checkUnique(scene.meshes, "mesh");
    checkUnique(scene.mappings, "mapping");
    for (std::size_t i = 0; i < doc["outputs"].size(); ++i)
      scene.outputs.push_back(output(doc["outputs"][i], "/outputs/" + std::to_string(i), scene));
    checkFiles(scene);
    return scene;
  }

 private:
  SceneCamera camera(const json& j, const std::string& pointer) const {
    SceneCamera c;
    c.name = j["name"];
    c.pointer = pointer;
    const param::ParameterDictionary parameters = sceneParameters(j, {"name"}, pointer);
    c.settings = at(pointer, [&] {
      const inspect::CameraSettings made = inspect::readCameraSettings(parameters);
      parameters.checkAllRead(inspect::cameraParameterNames());
      return made;
    });
    return c;
  }

  SceneTexture texture(const json& j, const std::string& pointer) const {
    SceneTexture t;
    t.name = j["name"];
    t.pointer = pointer;
    const param::ParameterDictionary parameters = sceneParameters(j, {"name"}, pointer);
    t.settings = at(pointer, [&] {
      const inspect::TextureSettings made = inspect::readTextureSettings(parameters, "source");
      parameters.checkAllRead(inspect::textureParameterNames("source"));
      return made;
    });
    t.settings.resolveFiles([&](const std::string& file) { return input(file, pointer + "/source"); });
    return t;
  }

  void mesh(const json& j, std::size_t index, Scene& scene) const {
    SceneMesh m;
    m.pointer = "/meshes/" + std::to_string(index);
    m.name = j["name"];
    m.path = input(j["path"], m.pointer + "/path");
    if (j.contains("model"))
      for (int k = 0; k < 16; ++k) m.model(k % 4, k / 4) = j["model"][std::size_t(k)].get<double>();
    scene.meshes.push_back(m);
    const json& mappings = j.value("mappings", json::array());
    for (std::size_t k = 0; k < mappings.size(); ++k)
      scene.mappings.push_back(mapping(mappings[k], m.pointer + "/mappings/" + std::to_string(k), index, scene));
  }

  SceneMapping mapping(const json& j, const std::string& pointer, std::size_t mesh, const Scene& scene) const {
    SceneMapping m;
    m.name = j["name"];
    m.pointer = pointer;
    m.mesh = mesh;
    const std::string kind = j["kind"];
    if (kind == "projector") {
      m.kind = SceneMapping::Kind::Projector;
      const param::ParameterDictionary parameters = sceneParameters(j, {"kind", "name"}, pointer);
      const param::ProjectorRequest projector = at(pointer, [&] {
        param::ProjectorRequest made = param::makeProjector(parameters);
        parameters.checkAllRead(param::projectorParameterNames());
        return made;
      });
      m.projector = projector.options;
      m.seamPlaceAuto = projector.seamPlaceAuto;
    } else if (kind == "texgen") {
      m.kind = SceneMapping::Kind::Texgen;
      const param::ParameterDictionary parameters =
          sceneParameters(j, {"kind", "name", "camera", "eye", "center", "up"}, pointer);
      m.texgen = at(pointer, [&] {
        const texgen::TexgenOptions made = inspect::readTexgen(parameters, "texgen", Mat4::Identity(), Mat4::Identity());
        parameters.checkAllRead(inspect::texgenOptionNames("texgen"));
        return made;
      });
      const bool lookAtGiven = j.contains("eye") || j.contains("center") || j.contains("up");
      if (j.contains("camera") && lookAtGiven) fail(pointer, "camera and eye, center, up exclude each other");
      if (j.contains("camera")) m.camera = find(scene.cameras, j["camera"], "camera", pointer + "/camera");
      const auto vec3 = [&](const char* key, Vec3 fallback) {
        return j.contains(key) ? Vec3(j[key][0].get<double>(), j[key][1].get<double>(), j[key][2].get<double>())
                               : fallback;
      };
      // As `uvtk texgen`: GL's initial view, the eye at the origin looking down -z.
      m.viewFromWorld = lookAt(vec3("eye", Vec3::Zero()), vec3("center", Vec3(0, 0, -1)), vec3("up", Vec3(0, 1, 0)));
    }
    return m;
  }

  SceneOutput output(const json& j, const std::string& pointer, const Scene& scene) const {
    SceneOutput o;
    o.pointer = pointer;
    o.path = output(j.value("path", ""), pointer + "/path");
    if (j.contains("mapping")) o.mapping = find(scene.mappings, j["mapping"], "mapping", pointer + "/mapping");
    if (j.contains("mesh")) o.mesh = find(scene.meshes, j["mesh"], "mesh", pointer + "/mesh");
    if (j.contains("camera")) o.camera = find(scene.cameras, j["camera"], "camera", pointer + "/camera");
    if (j.contains("texture")) o.texture = find(scene.textures, j["texture"], "texture", pointer + "/texture");
    const std::string kind = j["kind"];
    // report, compare: their own json
    // "obj" is the older name of "mesh", from when OBJ was the one format written.
    const bool mesh = kind == "mesh" || kind == "obj";
    if (mesh || kind == "render") o.json = output(j.value("json", ""), pointer + "/json");
    if (mesh) {
      o.kind = SceneOutput::Kind::Mesh;
      o.write.writeW = j.value("write_w", false);
      o.write.floatDigits = j.value("uv_digits", "double") == "float";
      o.write.ascii = j.value("ascii", false);
      at(pointer + "/path", [&] { io::checkMeshOutput(o.path, o.write, "path"); });
    } else if (kind == "render") {
      o.kind = SceneOutput::Kind::Render;
      const param::ParameterDictionary parameters =
          sceneParameters(j, {"kind", "mapping", "camera", "texture", "path", "json"}, pointer);
      o.frame = at(pointer, [&] {
        const inspect::FrameSettings made = inspect::readFrameSettings(parameters);
        parameters.checkAllRead(inspect::frameParameterNames());
        return made;
      });
      // The AOV file by default is the picture's with .exr (as checkFrameOutputs names it), checked as given.
      const bool aovNamed = !o.frame.aovOutput.empty();
      if (!o.frame.frame.aovs.empty() && !aovNamed)
        o.frame.aovOutput = fs::path(j.value("path", "")).replace_extension(".exr").string();
      o.frame.aovOutput = output(o.frame.aovOutput, pointer + (aovNamed ? "/aov_output" : "/path"));
      at(pointer, [&] { checkFrameOutputs(o.frame, o.path); });
      const SceneMapping& mapping = scene.mappings[*o.mapping];
      const TextureSettings& texture = o.texture ? scene.textures[*o.texture].settings : scene.defaultTexture;
      at(pointer, [&] {
        checkTextureUse(o.frame.frame, texture,
                        mapping.kind == SceneMapping::Kind::Projector ? &mapping.projector : nullptr);
      });
      if (o.frame.frame.needsExact() && scene.mappings[*o.mapping].kind == SceneMapping::Kind::File)
        fail(pointer, std::string(o.frame.frame.perPixel ? "uv per-pixel" : "view uverror") +
                          " evaluates the mapping at every pixel, and mapping \"" + scene.mappings[*o.mapping].name +
                          "\" is the file's own UVs");
    } else if (kind == "report") {
      o.kind = SceneOutput::Kind::Report;
      const param::ParameterDictionary parameters = sceneParameters(j, {"kind", "mapping"}, pointer);
      o.report = at(pointer, [&] {
        inspect::ReportOptions made = inspect::readReportOptions(parameters);
        parameters.checkAllRead(inspect::reportParameterNames());
        made.check();
        return made;
      });
      o.report.json = output(o.report.json, pointer + "/json");
      o.report.html = output(o.report.html, pointer + "/html");
      if (o.report.json.empty() && o.report.html.empty()) fail(pointer, "expected json, html or both");
    } else if (kind == "compare") {
      o.kind = SceneOutput::Kind::Compare;
      const param::ParameterDictionary parameters = sceneParameters(j, {"kind", "mesh"}, pointer);
      o.compare = at(pointer, [&] {
        const inspect::CompareOptions made = inspect::readCompareOptions(parameters);
        parameters.checkAllRead(inspect::compareParameterNames());
        return made;
      });
      o.compare.json = output(o.compare.json, pointer + "/json");
      o.compare.markdown = output(o.compare.markdown, pointer + "/markdown");
      o.compare.sheet = output(o.compare.sheet, pointer + "/sheet");
      o.compare.writeBest = output(o.compare.writeBest, pointer + "/write_best");
    } else if (kind == "bench") {
      o.kind = SceneOutput::Kind::Bench;
      o.bench = bench(j, pointer, o, scene);
    } else {
      o.kind = SceneOutput::Kind::Gallery;
      o.title = j.value("title", scene.title);
    }
    return o;
  }

  // `uvtk bench` of the mapping kernel on a mesh of the scene: that mesh's file, the projectors
  // named (or the one of `mapping`), quick by default. Neither the end-to-end `uvtk map`, which
  // forks, nor rendering: the schema has neither's keys.
  timing::BenchOptions bench(const json& j, const std::string& pointer, const SceneOutput& o,
                              const Scene& scene) const {
    if (j.contains("mesh") == j.contains("mapping")) fail(pointer, "expected mesh or mapping, one of them");
    // The output files are checked as a scene's (their folders are created when the scene runs).
    param::ParameterDictionary parameters =
        sceneParameters(j, {"kind", "mesh", "mapping", "path", "json", "markdown", "plot"}, pointer);
    // A look at the trade beside the pictures, not a measurement to publish.
    if (!j.contains("min_time")) parameters.add("min-time", 0.01);
    const SceneMapping* mapping = o.mapping ? &scene.mappings[*o.mapping] : nullptr;
    if (mapping) {
      for (const char* key : {"projector", "omap"})
        if (j.contains(key))
          fail(pointer + "/" + key,
               std::string(key) + " and mapping exclude each other: the mapping's projector is timed");
      if (mapping->kind != SceneMapping::Kind::Projector)
        fail(pointer + "/mapping",
             "mapping \"" + mapping->name + "\" is not a projector: `uvtk bench` times projectors");
      if (param::traitsOf(mapping->projector.surface).choosesPerTriangle)
        fail(pointer + "/mapping", "mapping \"" + mapping->name +
                                       "\" chooses a projection per triangle; `uvtk bench` times per-vertex mappings");
    }
    parameters.add("mesh", scene.meshes[mapping ? mapping->mesh : *o.mesh].path);
    parameters.add("no-end-to-end", true);
    timing::BenchOptions options = at(pointer, [&] {
      timing::BenchOptions made = timing::readBenchOptions(parameters);
      parameters.checkAllRead(timing::benchParameterNames());
      return made;
    });
    if (mapping) options.projectors = {{mapping->name, mapping->projector}};
    options.html = o.path;
    options.json = output(j.value("json", ""), pointer + "/json");
    options.markdown = output(j.value("markdown", ""), pointer + "/markdown");
    options.plot = output(j.value("plot", ""), pointer + "/plot");
    return options;
  }

  // No two outputs write the same file, and no output overwrites an input.
  void checkFiles(const Scene& scene) const {
    std::map<std::string, std::string> writers;
    // The paths have been checked; a system refusal here (a folder that cannot be searched) is the scene's.
    const auto canonical = [&](const std::string& file, const std::string& pointer) {
      std::error_code error;
      const fs::path resolved = fs::weakly_canonical(file, error);
      if (error) fail(pointer, quotedName(file) + ": " + error.message());
      return resolved.string();
    };
    for (const SceneMesh& m : scene.meshes) writers[canonical(m.path, m.pointer)] = m.pointer;
    for (const SceneOutput& o : scene.outputs)
      for (const std::string& file : o.files()) {
        const auto [where, inserted] = writers.emplace(canonical(file, o.pointer), o.pointer);
        if (!inserted) fail(o.pointer, "writes " + quotedName(file) + ", which " + where->second + " names too");
      }
  }

  std::string path_;
  fs::path inputDir_, outputDir_;
  bool allowOutside_ = false;
};

}  // namespace

bool SceneMapping::needsNormals() const {
  if (kind == Kind::Projector)
    return projector.ray == param::RayKind::ObjectNormal || projector.ray == param::RayKind::Reflection;
  if (kind == Kind::File) return false;
  return std::any_of(texgen.coordinates.begin(), texgen.coordinates.end(), [](const texgen::TexgenCoordinate& c) {
    return c.mode == texgen::TexgenMode::SphereMap || c.mode == texgen::TexgenMode::NormalMap ||
           c.mode == texgen::TexgenMode::ReflectionMap;
  });
}

std::vector<std::string> SceneOutput::files() const {
  std::vector<std::string> out;
  const auto add = [&out](const std::string& file) {
    if (!file.empty()) out.push_back(file);
  };
  add(path);
  if (kind == Kind::Mesh && io::meshFormatOf(path) == io::MeshFormat::gltf) add(io::gltfBufferPath(path));
  add(json);
  if (kind == Kind::Render && !frame.frame.aovs.empty()) add(frame.aovOutput);
  if (kind == Kind::Report) add(report.json), add(report.html);
  if (kind == Kind::Compare) add(compare.json), add(compare.markdown), add(compare.sheet), add(compare.writeBest);
  if (kind == Kind::Bench) add(bench.json), add(bench.markdown), add(bench.plot);
  return out;
}

std::string checkOutputPath(const std::string& path, const fs::path& outputDir, bool allowOutside) {
  const std::string name = quotedName(path);
  if (path.empty()) throw InputError("expected a file name, found \"\"");
  if (path.find('\0') != std::string::npos) throw InputError(name + ": a file name cannot hold a NUL byte");
  for (std::size_t begin = 0; begin <= path.size();) {
    const std::size_t end = std::min(path.find('/', begin), path.size());
    if (end - begin > NAME_MAX)
      throw InputError(name + ": a component of " + std::to_string(end - begin) + " bytes, more than the " +
                       std::to_string(NAME_MAX) + " a file name can have");
    begin = end + 1;
  }
  const fs::path normal = fs::path(path).lexically_normal();
  if (!normal.has_filename() || normal.filename() == "." || normal.filename() == ".." || path.back() == '/')
    throw InputError(name + " names a folder, not a file");
  const std::string folder = quotedName(outputDir.empty() ? "." : outputDir.string());
  if (!allowOutside && normal.is_absolute())
    throw InputError(name + " is an absolute path, outside the output folder " + folder +
                     " (uvtk run --allow-outside lets outputs leave it)");
  if (!allowOutside && !within(normal, "."))
    throw InputError(name + " leads outside the output folder " + folder +
                     " (uvtk run --allow-outside lets outputs leave it)");
  const fs::path resolved = (outputDir / normal).lexically_normal();
  if (resolved.native().size() >= PATH_MAX)
    throw InputError(name + ": " + std::to_string(resolved.native().size()) +
                     " bytes joined to the output folder, more than the " + std::to_string(PATH_MAX - 1) +
                     " a path can have");
  std::error_code error;
  if (fs::is_directory(resolved, error))
    throw InputError(name + ": " + quotedName(resolved.string()) + " is an existing folder");
  if (!allowOutside) {
    // The folders on the way, and the output itself, may be symbolic links: an output that is a
    // link is written where it leads (io/temporary_file.h), so the whole path is resolved.
    const auto orHere = [](const fs::path& f) { return f.empty() ? fs::path(".") : f; };
    // Absolute first: weakly_canonical keeps a relative folder that does not exist yet relative.
    const fs::path base = fs::weakly_canonical(fs::absolute(orHere(outputDir)), error);
    fs::path target = fs::absolute(resolved, error);
    // weakly_canonical stops at a dangling link, which the output would still be written through.
    for (int links = 0; !error && links < 40; ++links) {
      std::error_code missing;  // a name that does not exist yet is no link
      if (!fs::is_symlink(fs::symlink_status(target, missing))) break;
      const fs::path next = fs::read_symlink(target, error);
      target = next.is_absolute() ? next : target.parent_path() / next;
    }
    if (!error) target = fs::weakly_canonical(target, error);
    if (error) throw InputError(name + ": cannot resolve it in the output folder " + folder + ": " + error.message());
    if (!within(target, base))
      throw InputError(name + " leads outside the output folder " + folder + " through a symbolic link, to " +
                       quotedName(target.string()) + " (uvtk run --allow-outside lets outputs leave it)");
  }
  return resolved.string();
}

Scene loadScene(const std::string& path, const std::string& outputDir, bool allowOutside) {
  return SceneReader(path, outputDir, allowOutside).read();
}

}  // namespace uvtk::scene
