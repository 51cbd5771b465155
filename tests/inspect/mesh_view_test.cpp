// The 3D view's data (inspect/mesh_view.h): decoded here as the page's script decodes it (base64,
// zlib, little-endian arrays), and compared with the mesh, its UVs and its judgement.
#include "inspect/mesh_view.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "inspect/html_report.h"
#include "inspect/measures_json.h"
#include "meshes/generators.h"
#include "views/measure.h"

namespace uvtk::inspect {
namespace {
namespace UVTK_TEST_FILE {

std::string fromBase64(const std::string& text) {
  std::string out;
  std::uint32_t group = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    group = group << 6 | std::uint32_t(std::strchr(digits, c) - digits);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += char(group >> bits & 0xff);
    }
  }
  return out;
}

std::string inflated(const std::string& base64) {
  const std::string packed = fromBase64(base64);
  z_stream z{};
  EXPECT_EQ(inflateInit(&z), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
  z.avail_in = uInt(packed.size());
  std::string out;
  char chunk[65536];
  int status = Z_OK;
  while (status == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(chunk);
    z.avail_out = sizeof chunk;
    status = inflate(&z, Z_NO_FLUSH);
    out.append(chunk, sizeof chunk - z.avail_out);
  }
  EXPECT_EQ(status, Z_STREAM_END);
  inflateEnd(&z);
  return out;
}

template <class T>
std::vector<T> array(const nlohmann::json& data, const std::string& name) {
  const std::string bytes = inflated(data.at("blobs").at(name).get<std::string>());
  EXPECT_EQ(bytes.size() % sizeof(T), 0u) << name;
  std::vector<T> values(bytes.size() / sizeof(T));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

// The view's data, as the page's script reads it from its <script class="view3d-data">.
nlohmann::json viewData(const std::string& html) {
  const std::string open = "<script type=\"application/json\" class=\"view3d-data\">";
  const std::size_t begin = html.find(open);
  EXPECT_NE(begin, std::string::npos);
  const std::size_t end = html.find("</script>", begin);
  std::string json = html.substr(begin + open.size(), end - begin - open.size());
  for (std::size_t at = json.find("<\\/"); at != std::string::npos; at = json.find("<\\/", at)) json.replace(at, 3, "</");
  return nlohmann::json::parse(json);
}

double fromHalf(std::uint16_t bits) {
  const int exponent = bits >> 10 & 31, fraction = bits & 1023;
  const double magnitude = exponent == 0 ? std::ldexp(fraction, -24) : std::ldexp(1.0 + fraction / 1024.0, exponent - 15);
  return bits & 0x8000 ? -magnitude : magnitude;
}

MappedMesh sphereMapped(int segments, int rings, param::SurfaceKind surface) {
  param::ProjectorOptions options;
  options.surface = surface;
  options.placement.fit = param::Fit::BBox;
  return mapByProjector(meshes::latLongSphere(segments, rings), options, false, 1);
}

TEST(ViewMesh, UnderTheBudgetEveryFaceIsShownAsItIs) {
  const MappedMesh mapped = sphereMapped(16, 8, param::SurfaceKind::Sphere);
  const ViewMesh shown = viewMesh(mapped.mesh, mapped.uv, mapped.mesh.triangles.size());
  EXPECT_FALSE(shown.decimated);
  EXPECT_EQ(shown.mesh.triangles, mapped.mesh.triangles);
  EXPECT_EQ(shown.uv.uv, mapped.uv.uv);
  for (std::size_t f = 0; f < shown.faceOf.size(); ++f) EXPECT_EQ(shown.faceOf[f], f);
}

TEST(ViewMesh, AboveTheBudgetClustersVerticesAndKeepsEachFacesOwnUvs) {
  const MappedMesh mapped = sphereMapped(128, 64, param::SurfaceKind::Sphere);  // 16128 faces
  const std::size_t budget = 2000;
  const ViewMesh shown = viewMesh(mapped.mesh, mapped.uv, budget);
  ASSERT_TRUE(shown.decimated);
  EXPECT_LE(shown.mesh.triangles.size(), budget);
  EXPECT_GE(shown.mesh.triangles.size(), budget / 3);  // not collapsed to a handful
  ASSERT_EQ(shown.faceOf.size(), shown.mesh.triangles.size());
  std::set<std::size_t> distinct(shown.faceOf.begin(), shown.faceOf.end());
  EXPECT_EQ(distinct.size(), shown.faceOf.size());
  for (std::size_t f = 0; f < shown.faceOf.size(); ++f) {
    const Triangle& t = shown.mesh.triangles[f];
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "face " << f;
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(shown.uv.uv[3 * f + k], mapped.uv.uv[3 * shown.faceOf[f] + k]);
      // The shown vertex is its original vertex's cluster.
      EXPECT_EQ(t[k], shown.vertexOf[std::size_t(mapped.mesh.triangles[shown.faceOf[f]][k])]);
    }
    EXPECT_EQ(shown.uv.faceFlags[f], mapped.uv.faceFlags[shown.faceOf[f]]);
  }
  // A vertex moves at most a cell's diagonal; with ~2000 faces of a unit sphere, cells are < 0.1 across.
  for (std::size_t v = 0; v < mapped.mesh.positions.size(); ++v)
    EXPECT_LT((shown.mesh.positions[std::size_t(shown.vertexOf[v])] - mapped.mesh.positions[v]).norm(), 0.2);
  // The same input gives the same faces.
  EXPECT_EQ(viewMesh(mapped.mesh, mapped.uv, budget).faceOf, shown.faceOf);
}

TEST(MeshViewHtml, TheDataDecodesToTheMeshItsUvsAndItsJudgement) {
  const MappedMesh mapped = sphereMapped(24, 12, param::SurfaceKind::Sphere);
  const analysis::Judgement judgement = mapped.judge();
  const std::string html = meshViewHtml(mapped, judgement, {});
  EXPECT_EQ(html.rfind("<div class=\"view3d\">", 0), 0u);
  EXPECT_NE(html.find("All " + std::to_string(mapped.mesh.triangles.size()) + " faces."), std::string::npos);
  const nlohmann::json data = viewData(html);
  const std::size_t faces = mapped.mesh.triangles.size();
  EXPECT_EQ(data.at("faces"), faces);
  EXPECT_FALSE(data.at("blobs").contains("face_of"));  // not decimated: the shown face is the face

  const std::vector<std::uint8_t> status = array<std::uint8_t>(data, "status");
  ASSERT_EQ(status.size(), faces);
  for (std::size_t f = 0; f < faces; ++f) EXPECT_EQ(status[f], std::uint8_t(judgement.faces[f].status)) << "face " << f;

  // Corner k of face f: its split vertex holds the face's UV and (quantised) position.
  const std::vector<std::uint32_t> indices = array<std::uint32_t>(data, "indices");
  const std::vector<float> uvs = array<float>(data, "uvs");
  const std::vector<std::uint16_t> positions = array<std::uint16_t>(data, "positions");
  ASSERT_EQ(indices.size(), 3 * faces);
  ASSERT_EQ(positions.size() / 3, uvs.size() / 2);
  for (std::size_t c = 0; c < 3 * faces; ++c) {
    const std::size_t s = indices[c];
    ASSERT_LT(s, uvs.size() / 2);
    EXPECT_EQ(uvs[2 * s], float(mapped.uv.uv[c].x()));
    EXPECT_EQ(uvs[2 * s + 1], float(mapped.uv.uv[c].y()));
    // The sphere of radius 1 about the origin: its box is [-1, 1]^3, so positions are kept as they are.
    const Vec3 p = mapped.mesh.positions[std::size_t(mapped.mesh.triangles[c / 3][c % 3])];
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_NEAR(positions[3 * s + std::size_t(axis)] / 32767.5 - 1.0, p[axis], 1.0 / 32767.0);
  }

  // Measures: halves of the values the static views show, and their colour codes along the palette.
  const analysis::AreaTotals totals = analysis::okAreaTotals(judgement.faces);
  for (const views::View view : {views::View::Stretch, views::View::Area}) {
    const std::string name = views::toString(view);
    const std::vector<std::uint16_t> halves = array<std::uint16_t>(data, "values_" + name);
    const std::vector<std::uint8_t> codes = array<std::uint8_t>(data, "codes_" + name);
    const views::ColourScale scale = views::measureScale(view, judgement.faces, judgement.summary);
    for (std::size_t f = 0; f < faces; ++f) {
      const analysis::FaceDistortion& face = judgement.faces[f];
      if (face.status != analysis::FaceStatus::Ok) {
        EXPECT_EQ(codes[f], 240 + int(face.status));
        continue;
      }
      const double value = views::measureValue(view, face, totals);
      EXPECT_NEAR(fromHalf(halves[f]), value, std::ldexp(std::fabs(value), -11) + 1e-7) << name << " face " << f;
      EXPECT_EQ(codes[f], std::lround(scale.position(value) * 239)) << name << " face " << f;
    }
  }
  // Texel density travels as whole floats.
  EXPECT_EQ(data.at("float_measures"), nlohmann::json::array({"density"}));
  const std::vector<float> densities = array<float>(data, "values_density");
  ASSERT_EQ(densities.size(), faces);
  for (std::size_t f = 0; f < faces; ++f)
    if (judgement.faces[f].status == analysis::FaceStatus::Ok) {
      EXPECT_EQ(densities[f], float(views::measureValue(views::View::Density, judgement.faces[f], totals,
                                                        &judgement.summary.density)))
          << "face " << f;
    }
  // Every seam edge, as a segment with its class.
  EXPECT_EQ(array<std::uint8_t>(data, "seam_wrap").size(), judgement.summary.seams.wrapEdges + judgement.summary.seams.cutEdges);
  EXPECT_EQ(array<float>(data, "seam_points").size(), 6 * array<std::uint8_t>(data, "seam_wrap").size());
}

// A mesh at 2^-1030 (subnormal coordinates) or 2^1000 is shown with the shape it has at 1: its
// positions were divided by at least 1e-300, so a mesh below that became a point at the centre.
TEST(MeshViewHtml, PositionsDoNotDependOnTheMeshScale) {
  const MappedMesh atOne = sphereMapped(24, 12, param::SurfaceKind::Plane);
  const std::vector<std::uint16_t> reference =
      array<std::uint16_t>(viewData(meshViewHtml(atOne, atOne.judge(), {})), "positions");
  for (const int exponent : {-1030, 1000}) {
    SCOPED_TRACE("the sphere times 2^" + std::to_string(exponent));
    MappedMesh scaled = atOne;
    for (Vec3& p : scaled.mesh.positions) p = p.unaryExpr([&](double x) { return std::ldexp(x, exponent); });
    const std::vector<std::uint16_t> positions =
        array<std::uint16_t>(viewData(meshViewHtml(scaled, scaled.judge(), {})), "positions");
    ASSERT_EQ(positions.size(), reference.size());
    // Exact at 2^1000; at 2^-1030 the coordinates keep 44 bits, so a code may move by one.
    for (std::size_t k = 0; k < positions.size(); ++k)
      EXPECT_LE(std::abs(int(positions[k]) - int(reference[k])), exponent > 0 ? 0 : 1) << "coordinate " << k;
  }
}

TEST(MeshViewHtml, ExactValuesSurviveAsHalves) {
  // A plane mapped by the plane projector: stretch exactly 1 and area distortion exactly 0 on every face.
  param::ProjectorOptions options;
  options.surface = param::SurfaceKind::Plane;
  options.placement.fit = param::Fit::BBox;
  const MappedMesh mapped = mapByProjector(meshes::planeGrid(4, 4, 2.0, 2.0), options, false, 1);
  const analysis::Judgement judgement = mapped.judge();
  const nlohmann::json data = viewData(meshViewHtml(mapped, judgement, {}));
  for (const std::uint16_t half : array<std::uint16_t>(data, "values_stretch")) EXPECT_EQ(half, 0x3c00);  // 1.0
  for (const std::uint16_t half : array<std::uint16_t>(data, "values_area")) EXPECT_EQ(half & 0x7fff, 0);
}

TEST(MeshViewHtml, ADecimatedViewSaysSoAndNamesTheOriginalFaces) {
  const MappedMesh mapped = sphereMapped(64, 32, param::SurfaceKind::Cylinder);
  const analysis::Judgement judgement = mapped.judge();
  MeshViewOptions options;
  options.faceBudget = 500;
  const std::string html = meshViewHtml(mapped, judgement, options);
  EXPECT_NE(html.find("Decimated for the 3D view"), std::string::npos);
  const nlohmann::json data = viewData(html);
  const std::vector<std::uint32_t> faceOf = array<std::uint32_t>(data, "face_of");
  const std::vector<std::uint8_t> status = array<std::uint8_t>(data, "status");
  ASSERT_EQ(faceOf.size(), status.size());
  EXPECT_LE(faceOf.size(), 500u);
  for (std::size_t f = 0; f < faceOf.size(); ++f)
    EXPECT_EQ(status[f], std::uint8_t(judgement.faces[faceOf[f]].status));
  EXPECT_EQ(data.at("faces_total"), mapped.mesh.triangles.size());
}

TEST(HtmlReport, TheFirstScreenHasTheVerdictTheViewAndTheKeyMeasures) {
  const MappedMesh mapped = sphereMapped(24, 12, param::SurfaceKind::Sphere);
  const analysis::Judgement judgement = mapped.judge();
  nlohmann::json report = judgementJson(mapped, judgement);
  report["input"] = {{"path", "ball.obj"}};
  const std::string html = htmlReport(report, {}, meshViewHtml(mapped, judgement, {}));
  const std::size_t verdict = html.find("<section id=\"verdict\">"), view = html.find("<div class=\"view3d\">"),
                    measures = html.find("<table class=\"key-measures\">"), all = html.find("<h2>All measures</h2>");
  ASSERT_NE(verdict, std::string::npos);
  EXPECT_LT(verdict, view);
  EXPECT_LT(view, measures);
  EXPECT_LT(measures, all);
  EXPECT_NE(html.find("<script>", all), std::string::npos);  // three.js and the viewer, once, at the end
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  // Without a view, no script.
  EXPECT_EQ(htmlReport(report, {}).find("<script"), std::string::npos);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::inspect
