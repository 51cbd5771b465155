#include "inspect/mesh_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "core/error.h"
#include "core/math.h"
#include "core/markup.h"
#include "inspect/html_page.h"
#include "io/image_io.h"
#include "io/page_bytes.h"
#include "io/split_vertices.h"
#include "render/procedural.h"
#include "views/measure.h"
#include "views/palette.h"
#include "views/seam_marks.h"
#include "io/json_text.h"

namespace uvtk::inspect {

extern const char* const kThreeViewScript;  // third_party/three/three-view.min.js (generated: viewer_assets.cpp)
extern const char* const kViewerScript;      // inspect/viewer/viewer.js
extern const char* const kViewerStyle;       // inspect/viewer/viewer.css

namespace {

// A grid cell's key: its three coordinates in 21 bits each.
using CellKey = std::uint64_t;

// Per vertex, the cell of a grid with `cells` cells along the longest side of `box`.
std::vector<CellKey> cellsOf(const Mesh& mesh, const Eigen::AlignedBox3d& box, int cells) {
  // Halves: a box spanning -1e308 .. 1e308 does not overflow.
  const Vec3 lo = 0.5 * box.min();
  const double extent = (0.5 * box.max() - lo).maxCoeff();
  std::vector<CellKey> out(mesh.positions.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    CellKey key = 0;
    for (int axis = 2; axis >= 0; --axis) {
      const double t = extent > 0.0 ? (0.5 * mesh.positions[v][axis] - lo[axis]) / extent : 0.0;
      key = key << 21 | CellKey(std::clamp(int(t * cells), 0, cells - 1));
    }
    out[v] = key;
  }
  return out;
}

// The faces a grid of `cells` keeps: three distinct cells, the first face of each cell triple.
std::vector<std::size_t> keptFaces(const Mesh& mesh, const std::vector<CellKey>& cellOf) {
  struct Entry {
    std::array<CellKey, 3> cells;
    std::size_t face;
  };
  std::vector<Entry> entries;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::array<CellKey, 3> c{cellOf[std::size_t(mesh.triangles[f][0])], cellOf[std::size_t(mesh.triangles[f][1])],
                             cellOf[std::size_t(mesh.triangles[f][2])]};
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
    std::sort(c.begin(), c.end());
    entries.push_back({c, f});
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.cells != b.cells ? a.cells < b.cells : a.face < b.face; });
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (i == 0 || entries[i].cells != entries[i - 1].cells) kept.push_back(entries[i].face);
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace

ViewMesh viewMesh(const Mesh& mesh, const UvMap& uv, std::size_t faceBudget) {
  UVTK_CHECK(faceBudget >= 1 && uv.uv.size() == 3 * mesh.triangles.size() && uv.faceCount() == mesh.triangles.size());
  ViewMesh out;
  if (mesh.triangles.size() <= faceBudget) {
    out.mesh.positions = mesh.positions;
    out.mesh.triangles = mesh.triangles;
    out.uv = uv;
    out.faceOf.resize(mesh.triangles.size());
    std::iota(out.faceOf.begin(), out.faceOf.end(), std::size_t(0));
    out.vertexOf.resize(mesh.positions.size());
    std::iota(out.vertexOf.begin(), out.vertexOf.end(), 0);
    return out;
  }
  Eigen::AlignedBox3d box;
  for (const Vec3& p : mesh.positions) box.extend(p);
  // A closed surface keeps about two faces per occupied cell, and occupies about cells^2 of them.
  int cells = std::max(1, int(std::sqrt(double(faceBudget) / 2.0)));
  std::vector<CellKey> cellOf;
  std::vector<std::size_t> kept;
  for (int attempt = 0; attempt < 12; ++attempt) {
    std::vector<CellKey> tryCells = cellsOf(mesh, box, cells);
    std::vector<std::size_t> tryKept = keptFaces(mesh, tryCells);
    const bool fits = tryKept.size() <= faceBudget;
    if (fits && tryKept.size() >= kept.size()) {
      cellOf = std::move(tryCells);
      kept = std::move(tryKept);
    }
    // Faces grow about as cells^2: aim a little under the budget.
    const double factor = std::sqrt(0.9 * double(faceBudget) / double(std::max<std::size_t>(tryKept.size(), 1)));
    const int next = std::clamp(int(cells * factor), 1, (1 << 21) - 1);
    if ((fits && tryKept.size() >= faceBudget * 7 / 10) || next == cells) break;
    cells = next;
  }
  if (cellOf.empty()) cellOf = cellsOf(mesh, box, 1);  // one cell: no face, but the vertices map
  // Shown vertices: the occupied cells in key order, at the mean of their vertices.
  std::vector<CellKey> keys = cellOf;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  out.vertexOf.resize(mesh.positions.size());
  out.mesh.positions.assign(keys.size(), Vec3::Zero());
  std::vector<int> members(keys.size(), 0);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const int shown = int(std::lower_bound(keys.begin(), keys.end(), cellOf[v]) - keys.begin());
    out.vertexOf[v] = shown;
    out.mesh.positions[std::size_t(shown)] += 0.5 * mesh.positions[v];  // halves, as the box
    ++members[std::size_t(shown)];
  }
  for (std::size_t c = 0; c < keys.size(); ++c) out.mesh.positions[c] *= 2.0 / std::max(members[c], 1);
  out.faceOf = kept;
  out.decimated = true;
  for (const std::size_t f : kept) {
    const Triangle& t = mesh.triangles[f];
    out.mesh.triangles.push_back({out.vertexOf[std::size_t(t[0])], out.vertexOf[std::size_t(t[1])],
                                  out.vertexOf[std::size_t(t[2])]});
    for (int k = 0; k < 3; ++k) {
      out.uv.uv.push_back(uv.uv[3 * f + std::size_t(k)]);
      if (!uv.cornerInvalid.empty()) out.uv.cornerInvalid.push_back(uv.cornerInvalid[3 * f + std::size_t(k)]);
    }
    out.uv.faceFlags.push_back(uv.faceFlags[f]);
  }
  return out;
}

namespace {

// Little-endian bytes of the values (the machines uvtk builds on are little-endian, as WebGL's typed arrays).
template <class T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

std::string blob(const std::string& bytes) { return io::base64(io::zlibCompressed(bytes)); }

// The IEEE 754 half-precision number nearest `value` (ties to even), within +-65504: a hover text
// shows measures to 3 significant digits, and half the bytes keep a 100 k-face page small.
std::uint16_t toHalf(float value) {
  constexpr float kLargest = 65504.0f;
  value = std::clamp(value, -kLargest, kLargest);
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  const std::uint32_t sign = (bits >> 16) & 0x8000u;
  bits &= 0x7fffffffu;
  if (bits < 0x38800000u) {  // below 2^-14: a subnormal half, in units of 2^-24
    float magnitude;
    std::memcpy(&magnitude, &bits, sizeof magnitude);
    return std::uint16_t(sign | std::uint32_t(std::nearbyint(magnitude * 16777216.0f)));
  }
  const std::uint32_t rounded = bits + 0x0fffu + ((bits >> 13) & 1u);  // to nearest, ties to even
  return std::uint16_t(sign | ((rounded - 0x38000000u) >> 13));
}

// Positions in 16 bits per axis over the box [-1, 1]^3 they were normalised to: 1/32768 of the
// half-extent, below a pixel of any view.
std::uint16_t toUnit16(double x) { return std::uint16_t(std::lround((std::clamp(x, -1.0, 1.0) + 1.0) * 32767.5)); }

// What the checker and UV grid layers look up at a corner: (s, t), or (s / q, t / q) with texgen's
// q; 0 where the corner has no valid UV or its value is beyond a float's range (its face's status
// says so).
Vec2 shownUv(const MappedMesh& mapped, const UvMap& uv, std::size_t corner, std::size_t originalCorner) {
  Vec2 t = uv.uv[corner];
  if (!mapped.q.empty()) t /= mapped.q[originalCorner];
  const bool valid = uv.cornerValid(corner);
  return valid && t.allFinite() && t.cwiseAbs().maxCoeff() < 1e30 ? t : Vec2::Zero();
}

std::array<int, 3> rgb(const Vec3& colour) {
  return {int(std::lround(std::clamp(colour.x(), 0.0, 1.0) * 255.0)),
          int(std::lround(std::clamp(colour.y(), 0.0, 1.0) * 255.0)),
          int(std::lround(std::clamp(colour.z(), 0.0, 1.0) * 255.0))};
}

std::string cssColour(const Vec3& colour) {
  const std::array<int, 3> c = rgb(colour);
  return "rgb(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + ")";
}

// A legend as HTML: its title lines, its colour bar with the ticks, its swatches.
std::string legendHtml(const views::Legend& legend, const std::string& layer) {
  std::ostringstream html;
  html << "<div class=\"legend\" data-layer=\"" << xmlEscaped(layer) << "\" hidden>";
  for (const std::string& line : legend.title) html << "<div class=\"legend-title\">" << xmlEscaped(line) << "</div>";
  if (legend.bar) {
    const views::ColourScale& scale = legend.bar->scale;
    constexpr int kSteps = 90, kWidth = 360;  // the bar in steps of 4 pixels, each at its centre's colour
    html << "<svg class=\"legend-bar\" width=\"" << kWidth + 40 << "\" height=\"40\" role=\"img\" aria-label=\"colour bar\">";
    for (int k = 0; k < kSteps; ++k)
      html << "<rect x=\"" << 20 + k * kWidth / kSteps << "\" y=\"2\" width=\"" << kWidth / kSteps << "\" height=\"14\" fill=\""
           << cssColour(views::paletteColour(scale.palette, (k + 0.5) / kSteps)) << "\"/>";
    for (const views::Tick& tick : legend.bar->ticks) {
      const double x = 20.0 + kWidth * scale.position(tick.value);
      html << "<line x1=\"" << number(x) << "\" x2=\"" << number(x) << "\" y1=\"16\" y2=\"21\" stroke=\"#333\"/>"
           << "<text x=\"" << number(x) << "\" y=\"34\" text-anchor=\"middle\">" << xmlEscaped(tick.label) << "</text>";
    }
    html << "</svg>";
  }
  if (!legend.entries.empty()) {
    html << "<ul class=\"legend-entries\">";
    for (const views::LegendEntry& entry : legend.entries)
      html << "<li><span class=\"swatch\" style=\"background:" << cssColour(entry.colour) << "\"></span>"
           << xmlEscaped(entry.label) << "</li>";
    html << "</ul>";
  }
  html << "</div>";
  return html.str();
}

struct Layer {
  std::string name, label;
  std::string kind;  // "checker", "uvgrid", "faces"
};

constexpr int kRampCodes = 240;  // a measure's colour codes 0..239 along its palette; then the statuses

}  // namespace

std::string meshViewHtml(const MappedMesh& mapped, const analysis::Judgement& judgement,
                         const MeshViewOptions& options) {
  UVTK_CHECK(judgement.faces.size() == mapped.mesh.triangles.size());
  const ViewMesh shown = viewMesh(mapped.mesh, mapped.uv, options.faceBudget);
  const std::size_t faceCount = shown.mesh.triangles.size();

  // Corner UVs as the layers look them up, then the vertices split where they differ.
  UvMap lookup;
  lookup.faceFlags = shown.uv.faceFlags;
  lookup.uv.resize(3 * faceCount);
  for (std::size_t f = 0; f < faceCount; ++f)
    for (std::size_t k = 0; k < 3; ++k) lookup.uv[3 * f + k] = shownUv(mapped, shown.uv, 3 * f + k, 3 * shown.faceOf[f] + k);
  io::SplitVertexKey key;
  key.uvs = &lookup;
  const io::SplitVertices split = io::splitVertices(shown.mesh, key);

  // Positions about the box centre, in units of half its longest side: first times the power of two
  // that brings the largest coordinate to about 1 (exact; a mesh at 1e-310 keeps its shape), then
  // by halves (a box spanning -1e308 .. 1e308 does not overflow).
  Eigen::AlignedBox3d box;
  for (const Vec3& p : shown.mesh.positions) box.extend(p);
  const double unit = box.isEmpty() ? 1.0 : unitPowerOfTwo(std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff()));
  const Vec3 lo = box.isEmpty() ? Vec3::Zero() : Vec3(box.min() * unit), hi = box.isEmpty() ? Vec3::Zero() : Vec3(box.max() * unit);
  const Vec3 centre = 0.5 * lo + 0.5 * hi;
  const double extent = (0.5 * hi - 0.5 * lo).maxCoeff();
  const double half = extent > 0.0 ? extent : 1.0;  // a point: its one position at the centre
  auto normalised = [&](const Vec3& p) { return Vec3(2.0 * ((0.5 * (p * unit) - 0.5 * centre) / half)); };
  std::vector<std::uint16_t> positions;
  std::vector<float> uvs;
  for (std::size_t s = 0; s < split.size(); ++s) {
    const Vec3 p = normalised(shown.mesh.positions[std::size_t(split.vertex[s])]);
    positions.insert(positions.end(), {toUnit16(p.x()), toUnit16(p.y()), toUnit16(p.z())});
    const Vec2 t = lookup.uv[split.corner[s]];
    uvs.insert(uvs.end(), {float(t.x()), float(t.y())});
  }
  std::vector<std::uint32_t> indices(split.ofCorner.begin(), split.ofCorner.end());

  // Per shown face: its status, and per measure its value and colour code.
  const analysis::AreaTotals totals = analysis::okAreaTotals(judgement.faces);
  std::vector<std::uint8_t> status(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) status[f] = std::uint8_t(judgement.faces[shown.faceOf[f]].status);
  nlohmann::json data;
  std::vector<Layer> layers{{"checker", "checker (shaded)", "checker"}, {"uvgrid", "UV grid", "uvgrid"}};
  std::ostringstream legends;
  nlohmann::json blobs, tables = nlohmann::json::object(), measures = nlohmann::json::array();
  const analysis::TexelDensity& density = judgement.summary.density;
  std::vector<views::View> shownMeasures{views::View::Stretch, views::View::Linf, views::View::Angle, views::View::Area};
  if (density.finite) shownMeasures.push_back(views::View::Density);  // else no face has a density to show
  nlohmann::json fullValues = nlohmann::json::array();
  for (const views::View view : shownMeasures) {
    const std::string name = views::toString(view);
    const views::ColourScale scale = views::measureScale(view, judgement.faces, judgement.summary);
    // Densities span any range (texels per object unit): whole floats; the others as halves.
    const bool full = view == views::View::Density;
    std::vector<std::uint8_t> codes(faceCount);
    std::vector<std::uint16_t> halves(full ? 0 : faceCount, 0);
    std::vector<float> floats(full ? faceCount : 0, 0.0f);
    for (std::size_t f = 0; f < faceCount; ++f) {
      const analysis::FaceDistortion& face = judgement.faces[shown.faceOf[f]];
      const double value = analysis::isMeasured(face.status) ? views::measureValue(view, face, totals, &density) : 0.0;
      if (full)
        floats[f] = std::isfinite(float(value)) ? float(value) : 0.0f;
      else
        halves[f] = toHalf(float(value));
      codes[f] = face.status == analysis::FaceStatus::Ok
                     ? std::uint8_t(std::lround(scale.position(value) * (kRampCodes - 1)))
                     : std::uint8_t(kRampCodes + int(face.status));
    }
    if (full) fullValues.push_back(name);
    nlohmann::json table = nlohmann::json::array();
    for (int c = 0; c < kRampCodes; ++c) table.push_back(rgb(views::paletteColour(scale.palette, double(c) / (kRampCodes - 1))));
    for (int s = 0; s < analysis::kFaceStatusCount; ++s)
      table.push_back(s == 0 ? std::array<int, 3>{0, 0, 0} : rgb(views::statusColour(analysis::FaceStatus(s))));
    tables[name] = table;
    blobs["codes_" + name] = blob(bytesOf(codes));
    blobs["values_" + name] = blob(full ? bytesOf(floats) : bytesOf(halves));
    measures.push_back(name);
    const views::FaceColouring colouring = views::colourByMeasure(view, judgement);
    layers.push_back({name, colouring.legend.title.front(), "faces"});
    legends << legendHtml(colouring.legend, name);
  }
  // The status layer: ok faces neutral, every other status in its colour.
  {
    nlohmann::json table = nlohmann::json::array();
    views::Legend legend;
    legend.title = {"Face status"};
    for (int s = 0; s < analysis::kFaceStatusCount; ++s) {
      const auto st = analysis::FaceStatus(s);
      const Vec3 colour = st == analysis::FaceStatus::Ok ? views::kNeutralColour : views::statusColour(st);
      table.push_back(rgb(colour));
      if (judgement.summary.statusCounts[st] > 0)
        legend.entries.push_back({colour, std::string(analysis::toString(st)) + ": " +
                                              std::to_string(judgement.summary.statusCounts[st])});
    }
    tables["status"] = table;
    layers.push_back({"status", "face status (pole, flipped, invalid...)", "faces"});
    legends << legendHtml(legend, "status");
  }
  // Seams: each edge between its two shown vertices (an edge a decimation collapsed is left out).
  std::vector<float> seamPoints;
  std::vector<std::uint8_t> seamWrap;
  const views::SeamMarks marks = views::seamMarks(mapped.mesh, mapped.uv);
  for (const SeamEdge& edge : marks.edges) {
    const int a = shown.vertexOf[std::size_t(edge.a)], b = shown.vertexOf[std::size_t(edge.b)];
    if (a == b) continue;
    for (const int v : {a, b}) {
      const Vec3 p = normalised(shown.mesh.positions[std::size_t(v)]);
      seamPoints.insert(seamPoints.end(), {float(p.x()), float(p.y()), float(p.z())});
    }
    seamWrap.push_back(edge.wrap ? 1 : 0);
  }
  std::vector<std::uint32_t> faceOf(shown.faceOf.begin(), shown.faceOf.end());

  blobs["positions"] = blob(bytesOf(positions));
  blobs["uvs"] = blob(bytesOf(uvs));
  blobs["indices"] = blob(bytesOf(indices));
  blobs["status"] = blob(bytesOf(status));
  if (shown.decimated) blobs["face_of"] = blob(bytesOf(faceOf));
  blobs["seam_points"] = blob(bytesOf(seamPoints));
  blobs["seam_wrap"] = blob(bytesOf(seamWrap));
  data["blobs"] = blobs;
  data["tables"] = tables;
  data["measures"] = measures;
  data["float_measures"] = fullValues;
  data["layers"] = nlohmann::json::array();
  for (const Layer& layer : layers) data["layers"].push_back({{"name", layer.name}, {"label", layer.label}, {"kind", layer.kind}});
  data["statuses"] = nlohmann::json::array();
  data["measured"] = nlohmann::json::array();
  for (int s = 0; s < analysis::kFaceStatusCount; ++s) {
    data["statuses"].push_back(analysis::toString(analysis::FaceStatus(s)));
    data["measured"].push_back(analysis::isMeasured(analysis::FaceStatus(s)));
  }
  data["checks"] = options.checks;
  data["view_dir"] = {options.camera.viewDir.x(), options.camera.viewDir.y(), options.camera.viewDir.z()};
  data["up"] = {options.camera.up.x(), options.camera.up.y(), options.camera.up.z()};
  data["seam_colours"] = {{"wrap", rgb(views::kWrapSeamColour)}, {"cut", rgb(views::kCutColour)}};
  data["uvgrid"] = io::pngDataUri(render::uvGridImage(512));
  data["faces"] = faceCount;
  data["faces_total"] = mapped.mesh.triangles.size();

  std::ostringstream html;
  html << "<div class=\"view3d\">\n<div class=\"view3d-bar\"><label>Layer <select class=\"layers\">";
  for (const Layer& layer : layers)
    html << "<option value=\"" << xmlEscaped(layer.name) << "\">" << xmlEscaped(layer.label) << "</option>";
  html << "</select></label> <label><input type=\"checkbox\" class=\"show-seams\" checked> seams (<span style=\"color:"
       << cssColour(views::kWrapSeamColour) << "\">wrap " << judgement.summary.seams.wrapEdges
       << "</span>, <span style=\"color:" << cssColour(views::kCutColour) << "\">cut " << judgement.summary.seams.cutEdges
       << "</span>)</label> <button type=\"button\" class=\"reset\">Reset view</button>"
       << " <span class=\"help\">drag: turn &middot; right-drag or shift-drag: pan &middot; wheel or pinch: zoom</span></div>\n"
       << "<canvas></canvas>\n<div class=\"hover\">Point at a face for its index, status and measures.</div>\n"
       << "<div class=\"legends\">" << legends.str() << "</div>\n<p class=\"note\">";
  if (shown.decimated)
    html << "Decimated for the 3D view: " << faceCount << " of " << mapped.mesh.triangles.size()
         << " faces (vertex clustering, above " << options.faceBudget
         << " faces); each shown face has its own UVs, status and measures. The static views and every number "
            "below are of the whole mesh.";
  else
    html << "All " << faceCount << " faces.";
  std::string json = io::jsonText(data);
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at)) json.replace(at, 2, "<\\/");
  html << "</p>\n<script type=\"application/json\" class=\"view3d-data\">" << json << "</script>\n</div>\n";
  return html.str();
}

std::string meshViewScripts() {
  return std::string("<style>") + kViewerStyle + "</style>\n<script>" + kThreeViewScript + "</script>\n<script>" +
         kViewerScript + "</script>\n";
}

}  // namespace uvtk::inspect
