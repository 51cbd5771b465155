#include "inspect/check.h"

#include <cstdarg>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/uv_check.h"
#include "core/error.h"
#include "inspect/mapped_mesh.h"
#include "inspect/measures_json.h"
#include "inspect/run_report.h"
#include "inspect/texgen_job.h"
#include "inspect/verdict.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/mesh_reader.h"
#include "inspect/projector_json.h"
#include "param/projector_names.h"
#include "render/camera.h"
#include "views/corner_error.h"
#include "views/legend.h"
#include "io/json_text.h"

namespace uvtk::inspect {

namespace {

// The file's (u, v) per corner; a corner without vt is marked in cornerInvalid. Throws InputError
// for a face without vt unless `partial` or the file's writer listed it as having corners without
// a valid UV (io/face_lists.h), and for a file without any vt.
UvMap storedUvs(const io::ReadMeshResult& read, const std::string& path, bool partial) {
  const Mesh& mesh = read.mesh;
  std::vector<char> listed(mesh.faceCount(), 0);
  for (const std::size_t f : read.listedInvalidUvFaces) listed[f] = 1;
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
        if (!firstWithout && !listed[f]) firstWithout = f;
      }
    }
  if (firstWithout && (!partial || !any))
    throw InputError(path + ": error: expected texture coordinates (vt) on every face corner, found none on face " +
                     std::to_string(*firstWithout));
  return uv;
}

// What the stored UVs are compared with.
struct Reference {
  UvMap uv;  // the expected UVs, with the faces' flags, the corners without a value and those at a pole
  Vec2 period = Vec2::Zero();
  nlohmann::json record;    // "expected" in the JSON
  std::string description;  // one line of text
  std::string noValue;      // why a corner has no expected value
};

Reference byMapping(const Mesh& mesh, const CheckOptions& mapping, const std::string& inputPath) {
  Reference r;
  if (mapping.texgen) {
    MappedMesh mapped = mapByTexgen(mesh, *mapping.texgen);
    r.uv = std::move(mapped.uv);
    r.record = {{"source", "texgen"},
                {"coordinates", texgenCoordinatesJson(*mapping.texgen)},
                {"normalize", mapping.texgen->normalize},
                {"precision", param::precisionName(mapping.texgen->precision)}};
    r.noValue = "texgen's value is not finite";
    r.description = std::string("texgen (s ") + texgen::texgenModeName(mapping.texgen->coordinates[0].mode) + ", t " +
                    texgen::texgenModeName(mapping.texgen->coordinates[1].mode) + "), compared plainly";
    return r;
  }
  const param::ProjectorOptions& o = *mapping.projector;  // never --seam cut
  MappedMesh mapped = mapByProjector(mesh, o, mapping.seamPlaceAuto);
  printMappingNotes(inputPath, MeshWarnings{}, mapped);
  r.uv = std::move(mapped.uv);
  const bool wraps = param::traitsOf(o.surface).wraps;
  if (wraps) r.period = o.uvTransform.apply(Vec2(1, 0)) - o.uvTransform.apply(Vec2(0, 0));
  r.noValue = "the mapping has no value (the ray misses the surface, or the result is not finite)";
  r.record = {{"source", "projector"}, {"options", inspect::projectorOptionsJson(o)}};
  if (mapped.seamPlacement) r.record["seam_placement"] = inspect::seamPlacementJson(*mapped.seamPlacement);
  const nlohmann::json options = inspect::projectorOptionsJson(o);
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
  r.uv = storedUvs(other, path, partial);
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

nlohmann::json errorStatisticsJson(const analysis::ErrorStatistics& s, double texels) {
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

// printf into a string.
[[gnu::format(printf, 2, 3)]] void appendf(std::string& text, const char* format, ...) {
  va_list arguments, again;
  va_start(arguments, format);
  va_copy(again, arguments);
  const int size = std::vsnprintf(nullptr, 0, format, arguments);
  va_end(arguments);
  const std::size_t at = text.size();
  text.resize(at + std::size_t(size) + 1);
  std::vsnprintf(&text[at], std::size_t(size) + 1, format, again);
  va_end(again);
  text.resize(at + std::size_t(size));
}

void appendStatistics(std::string& text, const analysis::ErrorStatistics& s, double texels) {
  appendf(text, "  max error:  %.9g UV = %.9g texels\n", s.max, s.max * texels);
  appendf(text, "  p99 error:  %.9g UV = %.9g texels\n", s.p99, s.p99 * texels);
  appendf(text, "  mean error: %.9g UV = %.9g texels\n", s.mean, s.mean * texels);
}

// The report on stdout.
std::string checkText(const CheckOptions& a, const Report& report, const analysis::Judgement& judgement) {
  const Mesh& mesh = report.mesh;
  const analysis::UvCheck& check = report.check;
  const double texels = report.texels;
  std::string text;
  appendf(text, "uvtk check: %s: %zu vertices, %zu faces, %zu corners\n", a.input.c_str(), mesh.vertexCount(),
          mesh.faceCount(), check.error.size());
  appendf(text, "expected: %s\n", report.reference.description.c_str());
  appendf(text, "main corners: %zu (errors in UV units, and in texels of a %dx%d texture)\n", check.main.count,
          a.textureSize, a.textureSize);
  appendStatistics(text, check.main, texels);
  appendf(text,
          "pole corners: %zu, set apart (%zu at %zu pole vertices, u not compared; %zu other corners of %zu pole "
          "faces)\n",
          check.poleCorners + check.poleFaceCorners, check.poleCorners, poleVerticesOf(mesh, report.reference.uv).size(),
          check.poleFaceCorners, check.poleFaces);
  if (check.pole.count > 0) appendStatistics(text, check.pole, texels);
  appendf(text, "invalid corners: %zu (%zu where the reference has no value, %zu without vt)\n",
          check.invalidCorners.size(), check.noExpected, check.noFound);
  for (std::size_t i = 0; i < check.invalidCorners.size() && i < a.worst; ++i) {
    const std::size_t c = check.invalidCorners[i];
    appendf(text, "  face %zu corner %zu (vertex %d): %s\n", c / 3, c % 3, mesh.triangles[c / 3][c % 3],
            invalidReason(report, c).c_str());
  }
  if (check.invalidCorners.size() > a.worst)
    appendf(text, "  ... and %zu more (--json lists them all)\n", check.invalidCorners.size() - a.worst);
  appendf(text, "worst %zu of %zu main corners:\n", check.worst.size(), check.main.count);
  for (std::size_t i = 0; i < check.worst.size(); ++i) text += cornerLine(report, i + 1, check.worst[i]) + "\n";
  text += "the stored UVs as a layout: " + verdictLine(judgement) + "\n";
  if (!a.tolerance)
    text += "uvtk check: no --tolerance given: report only\n";
  else if (check.main.max <= *a.tolerance)
    text += "uvtk check: PASS\n";
  else
    appendf(text, "uvtk check: FAIL (max error %.9g > tolerance %.9g)\n", check.main.max, *a.tolerance);
  return text;
}

}  // namespace

CheckRun checkStoredUvs(const CheckOptions& a) {
  UVTK_CHECK(a.textureSize >= 1);
  const double texels = double(a.textureSize);
  const io::ReadMeshResult input = io::readMesh(a.input);
  printInputWarnings(a.input, input.warnings);
  const Mesh& mesh = input.mesh;
  const UvMap found = storedUvs(input, a.input, a.partial);
  const Reference reference =
      a.against.empty() ? byMapping(mesh, a, a.input) : byFile(mesh, a.input, a.against, a.wrapU, a.partial);
  UVTK_CHECK(reference.uv.faceCount() == mesh.faceCount());

  analysis::UvCheckOptions options;
  options.period = reference.period;
  options.poleCorners = reference.uv.cornerPole;
  options.worst = a.worst;
  const analysis::UvCheck check = analysis::checkUvs(reference.uv, found, options);
  // The stored UVs judged as any layout: their flips, overlap and seams, whatever the reference says.
  analysis::JudgementOptions judging;
  judging.thresholds = a.thresholds;
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
    nlohmann::json pole = errorStatisticsJson(check.pole, texels);
    pole["pole_vertex_corners"] = check.poleCorners;
    pole["pole_face_corners"] = check.poleFaceCorners;
    pole["pole_vertices"] = poleVerticesOf(mesh, reference.uv);
    pole["pole_faces"] = check.poleFaces;
    pole["worst"] = worstPole;
    const nlohmann::json j = {{"tool", {{"name", "uvtk"}, {"version", UVTK_VERSION}}},
                              {"input", inputJson(a.input, input)},
                              {"expected", reference.record},
                              {"period", {reference.period.x(), reference.period.y()}},
                              {"texture_size", a.textureSize},
                              {"corners", check.error.size()},
                              {"main", errorStatisticsJson(check.main, texels)},
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
    outputs.writeText(a.json, io::jsonText(j, 2) + "\n");
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
    in.title = {"UV error, stored vs expected, in texels of " + size + "×" + size,
                "max " + views::formatNumber(check.main.max * texels) + "   p99 " +
                    views::formatNumber(check.main.p99 * texels) + "   mean " +
                    views::formatNumber(check.main.mean * texels)};
    render::RenderOptions render;
    render.camera = render::frameSphere(render::boundingSphere(mesh.positions), a.viewDir, a.viewUp,
                                        render::Projection{}, a.viewWidth, a.viewHeight, a.input);
    io::writeImage(outputs, a.view, views::drawCornerError(in, render), io::PixelType::UInt8);
  }
  outputs.publish();
  return {checkText(a, report, judgement), pass, judgement.verdict};
}

}  // namespace uvtk::inspect
