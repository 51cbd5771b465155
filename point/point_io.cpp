#include "point/point_io.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/mesh_reader.h"
#include "inspect/mapping_parameters.h"
#include "param/projector_names.h"
#include "param/projector.h"
#include "point/point_evaluator.h"

namespace uvtk::point {

namespace {

const char* const kStdin = "<stdin>";

bool allFinite(const Vector3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") + 1 - first);
}

// One decimal number, the whole of `text`: what strtod reads in the C locale, without hexadecimal.
// nan, inf and infinity (any case, signed) are numbers; a value beyond double range reads as +-inf
// and one below it as the nearest subnormal or zero, as strtod rounds them.
bool parseNumber(const std::string& text, double& value) {
  if (text.empty() || text.find_first_of("xX") != std::string::npos || text[0] == ' ' || text[0] == '\t') return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

[[noreturn]] void rowError(std::size_t line, const std::string& message) {
  throw InputError(std::string(kStdin) + ":" + std::to_string(line) + ": error: " + message);
}

std::string excerpt(const std::string& text) { return text.size() <= 60 ? text : text.substr(0, 57) + "..."; }

// A content line: not blank and not a comment.
bool isContent(const std::string& line) {
  const std::string t = trim(line);
  return !t.empty() && t[0] != '#';
}

// ---- CSV rows -------------------------------------------------------------------------------

// The columns a CSV row may hold, in the order of a row without a header.
const char* const kColumnNames[9] = {"x", "y", "z", "nx", "ny", "nz", "ex", "ey", "ez"};

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

std::string columnList(const std::vector<int>& columns) {
  std::string names;
  for (int c : columns) names += (names.empty() ? "" : ",") + std::string(kColumnNames[c]);
  return names;
}

// The columns a header names (each an index into kColumnNames).
std::vector<int> headerColumns(const std::vector<std::string>& fields, std::size_t line) {
  std::vector<int> columns;
  bool seen[9] = {};
  for (const std::string& field : fields) {
    int found = -1;
    for (int c = 0; c < 9; ++c)
      if (field == kColumnNames[c]) found = c;
    if (found < 0)
      rowError(line,
               "expected a number or a column name (x, y, z, nx, ny, nz, ex, ey, ez), found '" + excerpt(field) + "'");
    if (seen[found]) rowError(line, "expected each column once in the header, found '" + field + "' twice");
    seen[found] = true;
    columns.push_back(found);
  }
  for (int group = 0; group < 9; group += 3) {
    const int count = seen[group] + seen[group + 1] + seen[group + 2];
    if (count == 3 || (count == 0 && group > 0)) continue;
    for (int c = group; c < group + 3; ++c)
      if (!seen[c])
        rowError(line, std::string("expected the columns ") + kColumnNames[group] + ", " + kColumnNames[group + 1] +
                           " and " + kColumnNames[group + 2] + (group == 0 ? "" : " together") +
                           " in the header, found no '" + kColumnNames[c] + "'");
  }
  return columns;
}

std::vector<PointRow> readCsv(std::istream& in) {
  std::vector<PointRow> rows;
  std::vector<int> columns;  // empty until the first content line fixes them
  std::size_t lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (!isContent(line)) continue;
    const std::vector<std::string> fields = splitFields(line);
    double value = 0.0;
    if (columns.empty()) {
      // A header: the first content line, when its first field is a word and not a number.
      const char first = fields[0].empty() ? '\0' : fields[0][0];
      if (((first >= 'a' && first <= 'z') || (first >= 'A' && first <= 'Z')) && !parseNumber(fields[0], value)) {
        columns = headerColumns(fields, lineNumber);
        continue;
      }
      if (fields.size() != 3 && fields.size() != 6 && fields.size() != 9)
        rowError(lineNumber,
                 "expected 3, 6 or 9 columns (x,y,z[,nx,ny,nz][,ex,ey,ez]), or a header naming them, found " +
                     std::to_string(fields.size()));
      for (int c = 0; c < int(fields.size()); ++c) columns.push_back(c);
    }
    if (fields.size() != columns.size())
      rowError(lineNumber, "expected " + std::to_string(columns.size()) + " columns (" + columnList(columns) +
                               "), found " + std::to_string(fields.size()));
    PointRow row;
    row.line = lineNumber;
    double values[9] = {};
    bool has[9] = {};
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (!parseNumber(fields[i], value))
        rowError(lineNumber, "expected a number in column " + std::to_string(i + 1) + " (" + kColumnNames[columns[i]] +
                                 "), found '" + excerpt(fields[i]) + "'");
      values[columns[i]] = value;
      has[columns[i]] = true;
    }
    row.position = {values[0], values[1], values[2]};
    if (has[3]) row.normal = Vector3{values[3], values[4], values[5]};
    if (has[6]) row.eye = Vector3{values[6], values[7], values[8]};
    rows.push_back(row);
  }
  return rows;
}

// ---- JSON-line rows -------------------------------------------------------------------------

// A JSON number, or a string spelling a non-finite one ("nan", "inf", "-inf"): JSON has none.
bool jsonNumber(const nlohmann::json& j, double& value) {
  if (j.is_number()) {
    value = j.get<double>();
    return true;
  }
  return j.is_string() && parseNumber(j.get<std::string>(), value) && !std::isfinite(value);
}

Vector3 jsonTriple(const nlohmann::json& object, const char* key, std::size_t line) {
  const nlohmann::json& j = object.at(key);
  Vector3 v{};
  bool ok = j.is_array() && j.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) ok = jsonNumber(j[i], v[i]);
  if (!ok)
    rowError(line, std::string("expected \"") + key +
                       "\" to be an array of 3 numbers (or \"nan\", \"inf\", "
                       "\"-inf\"), found " +
                       excerpt(j.dump()));
  return v;
}

std::vector<PointRow> readJsonLines(std::istream& in) {
  std::vector<PointRow> rows;
  std::size_t lineNumber = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineNumber;
    if (!isContent(line)) continue;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      rowError(lineNumber, "expected a JSON object {\"p\": [x, y, z], \"n\": [...], \"eye\": [...]}, found '" +
                               excerpt(trim(line)) + "'");
    for (const auto& item : j.items())
      if (item.key() != "p" && item.key() != "n" && item.key() != "eye")
        rowError(lineNumber, "expected the keys p, n and eye, found \"" + excerpt(item.key()) + "\"");
    if (!j.contains("p")) rowError(lineNumber, "expected the key p (the point), found " + excerpt(j.dump()));
    PointRow row;
    row.line = lineNumber;
    row.position = jsonTriple(j, "p", lineNumber);
    if (j.contains("n")) row.normal = jsonTriple(j, "n", lineNumber);
    if (j.contains("eye")) row.eye = jsonTriple(j, "eye", lineNumber);
    rows.push_back(row);
  }
  return rows;
}

// ---- Evaluation -----------------------------------------------------------------------------

std::string number(double x) {
  if (std::isnan(x)) return "nan";  // glibc would print -nan for a set sign bit
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string eyeText(const Vector3& e) { return number(e[0]) + "," + number(e[1]) + "," + number(e[2]); }

// `parameters` with the eye `eye` in place of theirs.
param::ParameterDictionary withEye(const param::ParameterDictionary& parameters, const Vector3& eye) {
  param::ParameterDictionary out(parameters.face());
  for (const param::Parameter& p : parameters.parameters())
    if (p.name != "eye") out.add(p.name, p.value, p.place);
  out.add("eye", std::vector<double>{eye[0], eye[1], eye[2]});
  return out;
}

// The evaluators of one run: the mapping as the options give it, and the one for the eye of the
// latest row that brought its own (rebuilt only when that eye changes).
class Evaluators {
 public:
  // `sensible`: the range rule's box of --mesh (param::sensibleBox); none without a mesh.
  Evaluators(const param::ParameterDictionary& parameters, const inspect::ResolvedMapping& mapping,
             const Affine3& frame, const std::optional<Eigen::AlignedBox3d>& sensible, bool defaultUsable)
      : parameters_(parameters), mapping_(mapping), frame_(frame), sensible_(sensible) {
    if (defaultUsable) default_.emplace(mapping_, frame_, "uvtk eval", sensible_);
  }

  // nullptr, with `reason` set, when this eye gives no mapping.
  const PointEvaluator* forEye(const std::optional<Vector3>& eye, std::string& reason) {
    if (!eye) return &*default_;
    if (lastEye_ && std::memcmp(lastEye_->data(), eye->data(), sizeof(Vector3)) == 0) {
      reason = lastReason_;
      return last_ ? &*last_ : nullptr;
    }
    lastEye_ = eye;
    last_.reset();
    lastReason_.clear();
    if (!allFinite(*eye)) {
      lastReason_ = "the eye is not finite";
    } else {
      try {
        if (mapping_.projector) {
          inspect::ResolvedMapping m = mapping_;
          m.projector->eye = Vec3((*eye)[0], (*eye)[1], (*eye)[2]);
          last_.emplace(m, frame_, "uvtk eval", sensible_);
        } else {  // texgen's view from this eye: the same path as --eye
          last_.emplace(inspect::readMapping(withEye(parameters_, *eye), param::Fit::None), frame_, "uvtk eval",
                        sensible_);
        }
      } catch (const UsageError& e) {
        lastReason_ = std::string("no view from this eye: ") + e.what();
      }
    }
    reason = lastReason_;
    return last_ ? &*last_ : nullptr;
  }

  bool needsNormal() const {
    if (default_) return default_->needsNormal();
    // Build a throwaway one at a placeholder eye to ask.
    inspect::ResolvedMapping m = mapping_;
    if (m.projector) m.projector->eye = Vec3(0, 0, 1);
    return PointEvaluator(m, frame_, "uvtk eval").needsNormal();
  }

 private:
  const param::ParameterDictionary& parameters_;
  inspect::ResolvedMapping mapping_;
  Affine3 frame_;
  std::optional<Eigen::AlignedBox3d> sensible_;
  std::optional<PointEvaluator> default_, last_;
  std::optional<Vector3> lastEye_;
  std::string lastReason_;
};

// One output line's values.
struct Output {
  PointRow row;
  Vector3 normal{}, eye{};
  Result result;
  std::string reason;
};

std::string csvQuote(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string jsonTripleText(const Vector3& v) {
  auto one = [](double x) { return std::isfinite(x) ? number(x) : "\"" + number(x) + "\""; };
  return "[" + one(v[0]) + "," + one(v[1]) + "," + one(v[2]) + "]";
}

// The first line of CSV output (JSON lines have none).
std::string outputHeader(TextFormat format, bool withNormals, bool withEyes, bool triplanar) {
  if (format != TextFormat::Csv) return "";
  return std::string("x,y,z") + (withNormals ? ",nx,ny,nz" : "") + (withEyes ? ",ex,ey,ez" : "") + ",u,v,w,q" +
         (triplanar ? ",u_x,v_x,u_y,v_y,u_z,v_z,weight_x,weight_y,weight_z" : "") + ",status,reason\n";
}

// One point's line of output; with `triplanar` the three projections and their weights too.
std::string outputLine(const Output& o, TextFormat format, bool withNormals, bool withEyes, bool triplanar) {
  const Result& r = o.result;
  const auto& uv = r.triplanarUv;
  const auto& weight = r.triplanarWeights;
  std::string text;
  if (format == TextFormat::Csv) {
    text = eyeText(o.row.position);
    if (withNormals) text += "," + eyeText(o.normal);
    if (withEyes) text += "," + eyeText(o.eye);
    text += "," + number(r.u) + "," + number(r.v) + "," + number(r.w) + "," + number(r.q);
    if (triplanar)
      for (const double x : {uv[0][0], uv[0][1], uv[1][0], uv[1][1], uv[2][0], uv[2][1], weight[0], weight[1], weight[2]})
        text += "," + number(x);
    return text + "," + statusName(r.status) + "," + csvQuote(o.reason) + "\n";
  }
  text = "{\"p\":" + jsonTripleText(o.row.position);
  if (withNormals) text += ",\"n\":" + jsonTripleText(o.normal);
  if (withEyes) text += ",\"eye\":" + jsonTripleText(o.eye);
  text += ",\"u\":" + number(r.u) + ",\"v\":" + number(r.v) + ",\"w\":" + number(r.w) + ",\"q\":" + number(r.q);
  if (triplanar) {
    const auto pair = [](const std::array<double, 2>& p) { return "[" + number(p[0]) + "," + number(p[1]) + "]"; };
    text += ",\"uv_x\":" + pair(uv[0]) + ",\"uv_y\":" + pair(uv[1]) + ",\"uv_z\":" + pair(uv[2]) + ",\"weights\":[" +
            number(weight[0]) + "," + number(weight[1]) + "," + number(weight[2]) + "]";
  }
  return text + ",\"status\":\"" + statusName(r.status) + "\",\"reason\":" + nlohmann::json(o.reason).dump() + "}\n";
}

}  // namespace

Vector3 parseTriple(const std::string& text, const char* option) {
  std::vector<std::string> items;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) items.push_back(item);
  if (!text.empty() && text.back() == ',') items.push_back("");
  Vector3 v{};
  bool ok = items.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) ok = parseNumber(trim(items[i]), v[i]);
  if (!ok) throw UsageError(std::string(option) + ": expected 3 comma-separated numbers x,y,z, found '" + text + "'");
  return v;
}

std::vector<PointRow> readPointRows(std::istream& in, TextFormat format) {
  return format == TextFormat::Csv ? readCsv(in) : readJsonLines(in);
}

EvalCounts evaluatePoints(const EvalJob& job, const param::ParameterDictionary& parameters) {
  const bool fromStdin = job.in != nullptr;
  std::vector<PointRow> rows = job.rows;
  // The mapping. A reflection without --eye is resolved at a placeholder eye when the rows bring
  // their own: each row must then have one.
  const bool isTexgen = inspect::asksForTexgen(parameters, "texgen");
  const bool eyeFromRows = !isTexgen && fromStdin && !parameters.given("eye") &&
                           parameters.getChoice("omap", param::kRayNames, param::RayKind::SurfaceNormal) ==
                               param::RayKind::Reflection;
  const param::ParameterDictionary read = eyeFromRows ? withEye(parameters, {0, 0, 1}) : parameters;
  inspect::ResolvedMapping resolved = inspect::readMapping(read, param::Fit::None);
  read.checkAllRead(inspect::mappingParameterNames());
  Affine3 frame = Affine3::Identity();
  std::optional<Eigen::AlignedBox3d> sensible;
  if (isTexgen && !job.mesh.empty())
    throw UsageError("--mesh: texgen has no placement to fit; --mesh goes with a projector only");
  if (resolved.projector) {
    param::ProjectorOptions& options = *resolved.projector;
    if (job.mesh.empty() && inspect::fitsToMesh(options))
      throw UsageError(
          "the placement is fitted to a mesh (--fit bbox, center, pca or obb, or --convention blender or assimp): "
          "give --mesh FILE, or use --fit none (with --center, --axis-dir, --ref-dir and --scale for an explicit "
          "placement)");
    if (job.mesh.empty() && resolved.seamPlaceAuto)
      throw UsageError("--seam-place auto places the seam on a mesh's faces: give --mesh FILE, or the angle");
    std::vector<Vec3> positions;
    if (!job.mesh.empty()) {
      const io::ReadMeshResult input = io::readMesh(job.mesh);
      if (resolved.seamPlaceAuto) {
        const param::SeamPlacement placed = param::placeSeam(input.mesh, options);
        options.placement.turnDegrees = placed.turnDegrees;
        param::printSeamPlacement(placed);
      }
      positions = input.mesh.positions;
    }
    frame = point::placementFor(options, positions);
    if (!positions.empty()) sensible = param::sensibleBox(positions, options, frame);
  }
  Evaluators evaluators(parameters, resolved, frame, sensible, !eyeFromRows);

  if (fromStdin) rows = readPointRows(*job.in, job.input);

  // Eyes: what each row is evaluated from, and whether the mapping reads one.
  const bool readsEye = isTexgen || resolved.projector->ray == param::RayKind::Reflection;
  Vector3 defaultEye{};
  if (isTexgen && parameters.given("eye")) {
    const Vec3 e = *parameters.getVector<3>("eye");
    defaultEye = {e.x(), e.y(), e.z()};
  } else if (!isTexgen && resolved.projector->eye) {
    defaultEye = {resolved.projector->eye->x(), resolved.projector->eye->y(), resolved.projector->eye->z()};
  }
  bool withNormals = job.defaultNormal.has_value(), withEyes = false;
  for (const PointRow& row : rows) {
    if (row.eye && !readsEye)
      rowError(row.line, "expected no eye (only --omap reflection and texgen read one), found an eye");
    if (!row.eye && eyeFromRows)
      rowError(row.line,
               "expected an eye (ex,ey,ez columns or \"eye\"): --omap reflection without --eye takes each "
               "row's, found none");
    withNormals = withNormals || row.normal.has_value();
    withEyes = withEyes || row.eye.has_value();
  }
  if (!withNormals && evaluators.needsNormal() && !rows.empty())
    throw UsageError(
        "this mapping reads the normal (--omap normal or reflection, --caps, --projector triplanar, or a texgen "
        "mode that uses normals): give --normal x,y,z, or nx,ny,nz columns (\"n\" in JSON lines)");

  // Every row was read and checked above: from here on each point is written as it is evaluated,
  // to the temporary of -o (renamed at the end) or to stdout.
  std::optional<io::AtomicFile> file;
  if (!job.output.empty()) file.emplace(job.output);
  const auto write = [&](const std::string& text) {
    if (file)
      file->stream() << text;
    else
      std::fwrite(text.data(), 1, text.size(), stdout);
  };
  const bool triplanar = !isTexgen && param::traitsOf(resolved.projector->surface).blendsProjections;
  write(outputHeader(job.format, withNormals, withEyes, triplanar));
  EvalCounts counts;
  counts.points = rows.size();
  for (const PointRow& row : rows) {
    Output o;
    o.row = row;
    o.normal = row.normal ? *row.normal : job.defaultNormal ? *job.defaultNormal : Vector3{};
    o.eye = row.eye ? *row.eye : defaultEye;
    const point::PointEvaluator* evaluator = evaluators.forEye(row.eye, o.reason);
    if (evaluator) {
      o.result = evaluator->at(row.position, o.normal);
      o.reason = o.result.reason;
    } else {
      o.result.position = row.position;
      o.result.status = Status::Invalid;
    }
    ++counts.byStatus[int(o.result.status)];
    write(outputLine(o, job.format, withNormals, withEyes, triplanar));
  }
  if (file) {
    file->commit();
  } else if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    throw OutputError("<stdout>: error: cannot write");
  }
  return counts;
}

EvalJob evalJobOf(const std::vector<std::string>& points, const std::vector<std::string>& normals, bool inputGiven) {
  const bool fromStdin = points.empty();
  if (!fromStdin && inputGiven)
    throw UsageError("--input describes rows on stdin; it does not go with --point");
  if (!fromStdin && normals.size() > 1 && normals.size() != points.size())
    throw UsageError("--normal: expected one normal for every point, or one per point (" +
                     std::to_string(points.size()) + "), found " + std::to_string(normals.size()));
  if (fromStdin && normals.size() > 1)
    throw UsageError(
        "--normal: with rows on stdin, expected at most one (the normal of rows without their own), "
        "found " +
        std::to_string(normals.size()) + "; give each row's normal in its nx,ny,nz or \"n\"");
  if (fromStdin && isatty(STDIN_FILENO))
    throw UsageError("expected --point x,y,z, or rows on stdin (CSV or JSON lines; see --help), found a terminal");
  EvalJob job;
  for (const std::string& p : points) job.rows.push_back({0, parseTriple(p, "--point"), {}, {}});
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Vector3 n = parseTriple(normals[i], "--normal");
    if (normals.size() == 1)
      job.defaultNormal = n;
    else
      job.rows[i].normal = n;
  }
  if (fromStdin) job.in = &std::cin;
  return job;
}

const char* const kEvalHelp = R"(
Points in: --point x,y,z (repeatable) with --normal x,y,z (one for all points, or one per point);
or, without --point, rows on stdin:
  --input csv   one point a line: x,y,z[,nx,ny,nz][,ex,ey,ez] (3, 6 or 9 columns), or any of
                these columns in the order an optional first line (header) names them, e.g.
                "x,y,z,ex,ey,ez"; blank lines and lines starting with # are skipped.
  --input json  one JSON object a line: {"p": [x, y, z], "n": [nx, ny, nz], "eye": [ex, ey, ez]};
                n and eye optional; "nan", "inf", "-inf" as strings for non-finite values.
  A single --normal is the normal of rows without their own. A row's eye replaces --eye: the
  reflection O-mapping's eye (projector) or the gluLookAt eye of texgen's view.
  nan, inf and numbers beyond double range are values: such a point is invalid, not an error.
  A malformed row is an error (exit 3): "<stdin>:LINE: error: expected ..., found ...".

Placement: --fit none by default (object coordinates, or --center/--axis-dir/--ref-dir/--scale).
--fit bbox|center|pca|obb and --convention blender|assimp fit the placement to --mesh FILE exactly
as `uvtk map` fits it; --seam-place auto places the seam on that mesh. --seam and --pole repair a
mesh's faces and do nothing here: each point gets its own value (as uvtk map --seam none --pole none).

Out (stdout, or -o FILE written atomically), one line per point, every number %.17g (it reads back
as the same double):
  --format csv   header x,y,z[,nx,ny,nz][,ex,ey,ez],u,v,w,q,status,reason; reason quoted
  --format json  {"p": [...], "n": [...], "eye": [...], "u", "v", "w", "q", "status", "reason"}
  --projector triplanar adds u_x,v_x,u_y,v_y,u_z,v_z,weight_x,weight_y,weight_z before status
  (JSON: "uv_x", "uv_y", "uv_z" pairs and "weights"); u, v are the dominant axis's projection.
  u, v: the projector's (u, v) or texgen's (s, t); w: the cube face id 0..5 (+X -X +Y -Y +Z -Z)
  with --cube-layout faces, texgen's r, else 0; q: texgen's q (not divided out), the camera
  projector's w_c (its u, v are already s/q, t/q), else 1.
  nx,ny,nz appear when normals were given, ex,ey,ez when rows brought eyes.
Status: ok; pole (on a wrapping surface's axis: v exact, u undefined and written 0; texgen: the
sphere map's singular point, s = t = 1/2); on-seam (u = 0 and u = 1 are the same point, or a cube
edge); invalid (no value: non-finite or zero input, the ray misses; u = v = 0). reason says why.
A summary goes to stderr: "uvtk eval: N points, K ok, P poles, S on seam, I invalid".
Exit status: 0 ok, 2 usage error, 3 malformed row or mesh, 4 output not writable.)";

}  // namespace uvtk::point
