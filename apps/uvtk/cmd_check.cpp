// `uvtk check`: the texture coordinates stored in a mesh file against those a mapping gives (any
// projector of `uvtk map`, with its conventions, or GL texgen), or against another file's, corner
// by corner; statistics, the worst corners, a JSON record, a heatmap, and a pass/fail status
// (docs/check.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "measures_json.h"
#include "verdict_cli.h"
#include "analysis/uv_check.h"
#include "commands.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "mapped_mesh.h"
#include "options/arithmetic_cli.h"
#include "options/cli_values.h"
#include "options/mapping_options.h"
#include "options/projector_cli.h"
#include "options/texgen_cli.h"
#include "render/camera.h"
#include "run_report.h"
#include "views/corner_error.h"
#include "views/legend.h"

namespace uvtk::cli {

namespace {

struct CheckArguments {
  std::string input, against, json, view;
  std::string viewSize = "512x512", viewDir = "0,0,1", viewUp = "0,1,0";
  std::string wrap = "none";
  std::optional<double> tolerance;
  int textureSize = 1024;
  int worst = 10;
  bool partial = false;
  MappingArguments mapping;
  std::vector<std::string> mappingOptions;  // every option addMappingOptions added
  VerdictArguments verdict;                 // of the stored UVs as a layout (docs/conventions.md §11)
};

// The file's (u, v) per corner; a corner without vt is marked in cornerInvalid. Throws InputError
// for a face without vt unless `partial`, and for a file without any vt.
UvMap storedUvs(const Mesh& mesh, const std::string& path, bool partial) {
  UvMap uv;
  const std::size_t faces = mesh.faceCount();
  uv.uv.assign(3 * faces, Vec2::Zero());
  uv.faceFlags.assign(faces, kFaceOk);
  uv.cornerInvalid.assign(3 * faces, 0);
  std::optional<std::size_t> firstWithout;
  bool any = false;
  for (std::size_t f = 0; f < faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t corner = 3 * f + std::size_t(k);
      const int t = mesh.hasTexcoords() ? mesh.cornerTexcoords[f][k] : -1;
      if (t >= 0) {
        uv.uv[corner] = mesh.texcoords[std::size_t(t)].head<2>();
        any = true;
      } else {
        uv.cornerInvalid[corner] = 1;
        uv.faceFlags[f] |= kFaceInvalid;
        if (!firstWithout) firstWithout = f;
      }
    }
  if (firstWithout && (!partial || !any))
    throw InputError(path + ": error: expected texture coordinates (vt) on every face corner, found none on face " +
                     std::to_string(*firstWithout));
  return uv;
}

// What the stored UVs are compared with.
struct Reference {
  UvMap uv;  // the expected UVs, with the faces' flags and the corners without a value
  std::vector<int> poleVertices;
  Vec2 period = Vec2::Zero();
  nlohmann::json record;    // "expected" in the JSON
  std::string description;  // one line of text
  std::string noValue;      // why a corner has no expected value
};

Reference byMapping(const Mesh& mesh, const ResolvedMapping& resolved, const std::string& inputPath) {
  Reference r;
  if (resolved.texgen) {
    MappedMesh mapped = mapByTexgen(mesh, *resolved.texgen);
    r.uv = std::move(mapped.uv);
    nlohmann::json modes = nlohmann::json::object();
    const char* const names[4] = {"s", "t", "r", "q"};
    for (int i = 0; i < 4; ++i) {
      const texgen::TexgenCoordinate& c = resolved.texgen->coordinates[std::size_t(i)];
      modes[names[i]] = {{"mode", texgenModeName(c.mode)}, {"plane", {c.plane[0], c.plane[1], c.plane[2], c.plane[3]}}};
    }
    r.record = {{"source", "texgen"},
                {"coordinates", modes},
                {"normalize", resolved.texgen->normalize},
                {"precision", precisionName(resolved.texgen->precision)}};
    r.noValue = "texgen's value is not finite";
    r.description = std::string("texgen (s ") + texgenModeName(resolved.texgen->coordinates[0].mode) + ", t " +
                    texgenModeName(resolved.texgen->coordinates[1].mode) + "), compared plainly";
    return r;
  }
  const param::ProjectorOptions& o = *resolved.projector;  // never --seam cut (runCheck refused it)
  MappedMesh mapped = mapByProjector(mesh, o, resolved.seamPlaceAuto);
  printMappingNotes(inputPath, MeshWarnings{}, mapped);
  r.uv = std::move(mapped.uv);
  r.poleVertices = mapped.projection->summary.poleVertexList;
  const bool wraps = o.surface == param::SurfaceKind::Sphere || o.surface == param::SurfaceKind::Cylinder;
  if (wraps) r.period = o.uvTransform.apply(Vec2(1, 0)) - o.uvTransform.apply(Vec2(0, 0));
  r.noValue = "the mapping has no value (the ray misses the surface, or the result is not finite)";
  r.record = {{"source", "projector"}, {"options", projectorOptionsJson(o)}};
  if (mapped.seamPlacement) r.record["seam_placement"] = seamPlacementJson(*mapped.seamPlacement);
  const nlohmann::json options = projectorOptionsJson(o);
  char period[96] = "";
  if (wraps) std::snprintf(period, sizeof period, ", u modulo the period (%.17g, %.17g)", r.period.x(), r.period.y());
  r.description = "projector " + options["projector"].get<std::string>() + " (omap " +
                  options["omap"].get<std::string>() + ", fit " + options["fit"].get<std::string>() + ")" +
                  (wraps ? std::string(period) : std::string(", compared plainly"));
  return r;
}

// Another file's UVs; the same vertices and triangles are required, positions are compared.
Reference byFile(const Mesh& mesh, const std::string& inputPath, const std::string& path, bool wrapU, bool partial) {
  const io::ReadMeshResult other = io::readMesh(path);
  printInputWarnings(path, other.warnings);
  const Mesh& b = other.mesh;
  if (b.vertexCount() != mesh.vertexCount() || b.faceCount() != mesh.faceCount())
    throw InputError(path + ": error: expected the topology of " + inputPath + " (" +
                     std::to_string(mesh.vertexCount()) + " vertices, " + std::to_string(mesh.faceCount()) +
                     " faces), found " + std::to_string(b.vertexCount()) + " vertices, " +
                     std::to_string(b.faceCount()) + " faces");
  for (std::size_t f = 0; f < mesh.faceCount(); ++f)
    if (b.triangles[f] != mesh.triangles[f]) {
      const auto text = [](const Triangle& t) {
        return std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1);
      };
      throw InputError(path + ": error: expected face " + std::to_string(f) + " on vertices " +
                       text(mesh.triangles[f]) + " as in " + inputPath + ", found " + text(b.triangles[f]));
    }
  double farthest = 0.0;
  std::size_t at = 0, differing = 0;
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    const double d = (b.positions[v] - mesh.positions[v]).norm();
    differing += d > 0.0 || b.positions[v] != mesh.positions[v];
    if (d > farthest) farthest = d, at = v;
  }
  Reference r;
  r.uv = storedUvs(b, path, partial);
  r.uv.faceFlags.assign(b.faceCount(), kFaceOk);  // the corners without vt are marked in cornerInvalid
  if (wrapU) r.period = Vec2(1, 0);
  r.noValue = "no vt in " + path;
  r.record = {{"source", "file"},
              {"path", path},
              {"wrap", wrapU ? "u" : "none"},
              {"positions_differing", differing},
              {"position_max_distance", farthest}};
  if (differing > 0) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "uvtk check: warning: %s: %zu vertex positions differ from %s (largest distance %.9g, vertex %zu)",
                  path.c_str(), differing, inputPath.c_str(), farthest, at);
    std::fprintf(stderr, "%s\n", line);
  }
  r.description = "the UVs of " + path + (wrapU ? ", u modulo 1" : ", compared plainly");
  return r;
}

nlohmann::json statisticsJson(const analysis::ErrorStatistics& s, double texels) {
  return {{"corners", s.count},
          {"max", s.max},
          {"p99", s.p99},
          {"mean", s.mean},
          {"max_texels", s.max * texels},
          {"p99_texels", s.p99 * texels},
          {"mean_texels", s.mean * texels}};
}

struct Report {
  const Mesh& mesh;
  const Reference& reference;
  const UvMap& expected;
  const UvMap& found;
  const analysis::UvCheck& check;
  double texels;
};

nlohmann::json cornerJson(const Report& r, const analysis::CornerError& e) {
  const std::size_t f = e.corner / 3, k = e.corner % 3;
  const int vertex = r.mesh.triangles[f][k];
  const Vec3& p = r.mesh.positions[std::size_t(vertex)];
  const Vec2 &x = r.expected.uv[e.corner], &y = r.found.uv[e.corner];
  return {{"face", f},
          {"corner", k},
          {"vertex", vertex},
          {"position", {p.x(), p.y(), p.z()}},
          {"expected", {x.x(), x.y()}},
          {"found", {y.x(), y.y()}},
          {"error", e.error},
          {"error_texels", e.error * r.texels}};
}

std::string cornerLine(const Report& r, std::size_t rank, const analysis::CornerError& e) {
  const std::size_t f = e.corner / 3, k = e.corner % 3;
  const int vertex = r.mesh.triangles[f][k];
  const Vec3& p = r.mesh.positions[std::size_t(vertex)];
  const Vec2 &x = r.expected.uv[e.corner], &y = r.found.uv[e.corner];
  char line[512];
  std::snprintf(line, sizeof line,
                "  %zu. face %zu corner %zu (vertex %d) at (%.9g, %.9g, %.9g): expected (%.17g, %.17g), found (%.17g, "
                "%.17g), error %.9g UV = %.9g texels",
                rank, f, k, vertex, p.x(), p.y(), p.z(), x.x(), x.y(), y.x(), y.y(), e.error, e.error * r.texels);
  return line;
}

std::string invalidReason(const Report& r, std::size_t corner) {
  const bool noVt = !r.found.cornerInvalid.empty() && r.found.cornerInvalid[corner];
  const bool noValue = !r.expected.cornerInvalid.empty() && r.expected.cornerInvalid[corner];
  return noVt && noValue ? "no vt in the file; " + r.reference.noValue
         : noVt          ? "no vt in the file"
                         : r.reference.noValue;
}

void printStatistics(const analysis::ErrorStatistics& s, double texels) {
  std::printf("  max error:  %.9g UV = %.9g texels\n", s.max, s.max * texels);
  std::printf("  p99 error:  %.9g UV = %.9g texels\n", s.p99, s.p99 * texels);
  std::printf("  mean error: %.9g UV = %.9g texels\n", s.mean, s.mean * texels);
}

void runCheck(CheckArguments& a) {
  // Every option first, so that nothing is read or written for a bad command line.
  if (a.textureSize < 1) throw UsageError("--texture-size: expected a positive number of texels");
  if (a.worst < 0) throw UsageError("--worst: expected a count of corners, 0 or more");
  if (a.tolerance && !(std::isfinite(*a.tolerance) && *a.tolerance >= 0.0))
    throw UsageError("--tolerance: expected a finite number of UV units, 0 or more");
  if (a.wrap != "none" && a.wrap != "u") throw UsageError("--wrap: expected none or u, found \"" + a.wrap + "\"");
  const bool againstFile = !a.against.empty();
  std::optional<ResolvedMapping> resolved;
  if (againstFile) {
    for (const std::string& name : a.mappingOptions)
      if (given(a.mapping.app, name.c_str()))
        throw UsageError("--against compares two files: " + name + " (a mapping option) does not go with it");
  } else {
    if (given(a.mapping.app, "--wrap"))
      throw UsageError("--wrap goes with --against only: a mapping knows its own period");
    resolved = resolveMapping(a.mapping);
    if (resolved->projector && resolved->projector->seam == param::SeamMode::Cut)
      throw UsageError(
          "--seam cut changes the triangles, and uvtk check compares corner by corner: use --seam shift or none (u "
          "is compared modulo its period, so the seam's side does not matter)");
  }
  std::pair<int, int> viewSize{0, 0};
  if (!a.view.empty()) {
    viewSize = parseImageSize(a.viewSize, "--view-size");
    parseVec3(a.viewDir, "--view-dir");
    parseVec3(a.viewUp, "--view-up");
    io::checkImageType(a.view, io::PixelType::UInt8);
  }
  const double texels = double(a.textureSize);

  const io::ReadMeshResult input = io::readMesh(a.input);
  printInputWarnings(a.input, input.warnings);
  const Mesh& mesh = input.mesh;
  const UvMap found = storedUvs(mesh, a.input, a.partial);
  const Reference reference =
      againstFile ? byFile(mesh, a.input, a.against, a.wrap == "u", a.partial) : byMapping(mesh, *resolved, a.input);
  UVTK_CHECK(reference.uv.faceCount() == mesh.faceCount());

  analysis::UvCheckOptions options;
  options.period = reference.period;
  options.poleCorners = analysis::poleCornerMask(mesh, reference.poleVertices);
  options.worst = std::size_t(a.worst);
  const analysis::UvCheck check = analysis::checkUvs(reference.uv, found, options);
  // The stored UVs judged as any layout: their flips, overlap and seams, whatever the reference says.
  analysis::JudgementOptions judging;
  judging.thresholds = a.verdict.thresholds();
  const analysis::Judgement judgement = analysis::judge(mesh, found, judging);
  const Report report{mesh, reference, reference.uv, found, check, texels};

  const bool decided = a.tolerance.has_value();
  const bool pass = !decided || check.main.max <= *a.tolerance;
  const std::string status = !decided ? "report" : pass ? "pass" : "fail";

  io::OutputSet outputs;  // the record and the view, published together
  if (!a.json.empty()) {
    nlohmann::json worst = nlohmann::json::array(), worstPole = nlohmann::json::array();
    for (const analysis::CornerError& e : check.worst) worst.push_back(cornerJson(report, e));
    for (const analysis::CornerError& e : check.worstPole) worstPole.push_back(cornerJson(report, e));
    nlohmann::json invalid = nlohmann::json::array();
    for (std::size_t c : check.invalidCorners)
      invalid.push_back({{"face", c / 3},
                         {"corner", c % 3},
                         {"vertex", mesh.triangles[c / 3][c % 3]},
                         {"reason", invalidReason(report, c)}});
    nlohmann::json pole = statisticsJson(check.pole, texels);
    pole["pole_vertex_corners"] = check.poleCorners;
    pole["pole_face_corners"] = check.poleFaceCorners;
    pole["pole_vertices"] = reference.poleVertices;
    pole["pole_faces"] = check.poleFaces;
    pole["worst"] = worstPole;
    const nlohmann::json j = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                              {"input", inputJson(a.input, input)},
                              {"expected", reference.record},
                              {"period", {reference.period.x(), reference.period.y()}},
                              {"texture_size", a.textureSize},
                              {"corners", check.error.size()},
                              {"main", statisticsJson(check.main, texels)},
                              {"pole", pole},
                              {"invalid",
                               {{"corners", check.invalidCorners.size()},
                                {"no_reference_value", check.noExpected},
                                {"no_vt", check.noFound},
                                {"list", invalid}}},
                              {"worst", worst},
                              {"tolerance", a.tolerance ? nlohmann::json(*a.tolerance) : nlohmann::json(nullptr)},
                              {"status", status},
                              {"stored_uvs_verdict", analysis::toString(judgement.verdict)},
                              {"stored_uvs_reasons", reasonsJson(judgement)}};
    outputs.writeText(a.json, j.dump(2) + "\n");
  }

  if (!a.view.empty()) {
    views::CornerErrorInput in;
    in.mesh = &mesh;
    in.texels.resize(check.error.size());
    for (std::size_t c = 0; c < check.error.size(); ++c) in.texels[c] = check.error[c] * texels;
    in.faces.assign(mesh.faceCount(), views::CheckedFace::Compared);
    for (std::size_t c = 0; c < check.error.size(); ++c) {
      views::CheckedFace& face = in.faces[c / 3];
      if (check.cornerClass[c] == analysis::CornerClass::Invalid)
        face = views::CheckedFace::NoValue;
      else if (check.cornerClass[c] != analysis::CornerClass::Main && face == views::CheckedFace::Compared)
        face = views::CheckedFace::Pole;
    }
    const std::string size = std::to_string(a.textureSize);
    in.title = {"UV ERROR, STORED VS EXPECTED,", "IN TEXELS OF " + size + "X" + size,
                "MAX " + views::formatNumber(check.main.max * texels) + "  P99 " +
                    views::formatNumber(check.main.p99 * texels) + "  MEAN " +
                    views::formatNumber(check.main.mean * texels)};
    render::RenderOptions render;
    render.camera =
        render::frameSphere(render::boundingSphere(mesh.positions), parseVec3(a.viewDir, "--view-dir"),
                            parseVec3(a.viewUp, "--view-up"), render::Projection{}, viewSize.first, viewSize.second);
    io::writeImage(outputs, a.view, views::drawCornerError(in, render), io::PixelType::UInt8);
  }
  outputs.publish();

  std::printf("uvtk check: %s: %zu vertices, %zu faces, %zu corners\n", a.input.c_str(), mesh.vertexCount(),
              mesh.faceCount(), check.error.size());
  std::printf("expected: %s\n", reference.description.c_str());
  std::printf("main corners: %zu (errors in UV units, and in texels of a %dx%d texture)\n", check.main.count,
              a.textureSize, a.textureSize);
  printStatistics(check.main, texels);
  std::printf(
      "pole corners: %zu, set apart (%zu at %zu pole vertices, u not compared; %zu other corners of %zu pole "
      "faces)\n",
      check.poleCorners + check.poleFaceCorners, check.poleCorners, reference.poleVertices.size(),
      check.poleFaceCorners, check.poleFaces);
  if (check.pole.count > 0) printStatistics(check.pole, texels);
  std::printf("invalid corners: %zu (%zu where the reference has no value, %zu without vt)\n",
              check.invalidCorners.size(), check.noExpected, check.noFound);
  for (std::size_t i = 0; i < check.invalidCorners.size() && i < std::size_t(a.worst); ++i) {
    const std::size_t c = check.invalidCorners[i];
    std::printf("  face %zu corner %zu (vertex %d): %s\n", c / 3, c % 3, mesh.triangles[c / 3][c % 3],
                invalidReason(report, c).c_str());
  }
  if (check.invalidCorners.size() > std::size_t(a.worst))
    std::printf("  ... and %zu more (--json lists them all)\n", check.invalidCorners.size() - std::size_t(a.worst));
  std::printf("worst %zu of %zu main corners:\n", check.worst.size(), check.main.count);
  for (std::size_t i = 0; i < check.worst.size(); ++i)
    std::printf("%s\n", cornerLine(report, i + 1, check.worst[i]).c_str());
  std::printf("the stored UVs as a layout: %s\n", verdictLine(judgement).c_str());
  if (!decided)
    std::printf("uvtk check: no --tolerance given: report only\n");
  else if (pass)
    std::printf("uvtk check: PASS\n");
  else
    std::printf("uvtk check: FAIL (max error %.9g > tolerance %.9g)\n", check.main.max, *a.tolerance);
  std::fflush(stdout);
  if (!pass) throw CheckFailure("the check failed");
  enforceVerdict(a.verdict, judgement.verdict, "uvtk check");  // exit status 1 (2, 3, 4: usage, input, output errors)
}

}  // namespace

void addCheckCommand(CLI::App& root) {
  auto a = std::make_shared<CheckArguments>();
  CLI::App* cmd = root.add_subcommand(
      "check", "Compare the UVs stored in a mesh file with a mapping's (or another file's), corner by corner");
  cmd->add_option("input", a->input, "Mesh with texture coordinates (.obj with vt)")->required();
  cmd->add_option("--against", a->against,
                  "Compare with this file's UVs instead of a mapping (same vertices and faces)");
  cmd->add_option("--wrap", a->wrap, "--against: none, or u (compare u modulo 1)")
      ->type_name("none|u")
      ->capture_default_str();
  cmd->add_option("--tolerance", a->tolerance,
                  "Exit status 1 when the largest error of the main corners exceeds this (UV units); without it the "
                  "check only reports");
  cmd->add_option("--texture-size", a->textureSize, "Texels per UV unit for the errors in texels")
      ->capture_default_str();
  cmd->add_option("--worst", a->worst, "How many of the worst corners to list")->capture_default_str();
  cmd->add_flag("--partial", a->partial,
                "Accept faces without vt: their corners are listed as invalid instead of an input error");
  cmd->add_option("--json", a->json, "Also write everything as JSON");
  cmd->add_option("--view", a->view, "Also draw the per-corner error as a heatmap (PNG)");
  cmd->add_option("--view-size", a->viewSize, "The heatmap's viewport WxH (the legend is added below)")
      ->capture_default_str();
  cmd->add_option("--view-dir", a->viewDir, "The heatmap's camera: direction from the mesh to the eye")
      ->capture_default_str();
  cmd->add_option("--view-up", a->viewUp, "The heatmap's camera: up")->capture_default_str();
  std::vector<std::string> before;
  for (const CLI::Option* option : cmd->get_options()) before.push_back(option->get_name());
  addMappingOptions(*cmd, a->mapping, param::Fit::BBox);
  for (const CLI::Option* option : cmd->get_options()) {
    const std::string name = option->get_name();
    if (std::find(before.begin(), before.end(), name) == before.end() && name != "--help")
      a->mappingOptions.push_back(name);
  }
  addVerdictOptions(*cmd, a->verdict);
  cmd->callback([a] { runCheck(*a); });
}

}  // namespace uvtk::cli
