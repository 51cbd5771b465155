// `uvtk eval` as a user runs it: hand-computed values of every surface and texgen, the statuses,
// the input formats, the 17-digit round trip, agreement with `uvtk map`, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "apps/cli_test.h"
#include "io/mesh_reader.h"
#include "options/mapping_options.h"
#include "point/point_evaluator.h"
#include "doubles.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

// The CSV `uvtk eval` writes: a header, then rows whose last field (reason) is quoted.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::string text(std::size_t row, const std::string& column) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == column) return rows.at(row).at(c);
    ADD_FAILURE() << "no column " << column;
    return "";
  }
  double number(std::size_t row, const std::string& column) const {
    const std::string t = text(row, column);
    char* end = nullptr;
    const double value = std::strtod(t.c_str(), &end);
    EXPECT_EQ(end, t.c_str() + t.size()) << "not a number: " << t;
    return value;
  }
};

std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

Table parseCsv(const std::string& text) {
  Table table;
  std::istringstream in(text);
  std::string line;
  if (std::getline(in, line)) table.header = csvFields(line);
  while (std::getline(in, line)) table.rows.push_back(csvFields(line));
  return table;
}

std::string g17(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

class EvalCli : public CliTest {
 protected:
  // Runs `uvtk eval ARGS` with `input` on stdin; its stdout lands in `out`.
  CliRun eval(const std::string& args, const std::string& input = "") {
    writeText("stdin.txt", input);
    const CliRun r =
        shell(std::string(UVTK_BINARY) + " eval " + args + " < " + path("stdin.txt") + " > " + path("stdout.txt"));
    out = readText(path("stdout.txt"));
    return r;
  }
  // Runs it and parses its CSV output, expecting success.
  Table csv(const std::string& args, const std::string& input = "") {
    const CliRun r = eval(args, input);
    EXPECT_EQ(r.status, 0) << r.err;
    return parseCsv(out);
  }

  std::string out;
};

// ---- Hand-computed values -------------------------------------------------------------------

TEST_F(EvalCli, SphereGivesExactQuarterTurnOnTheEquator) {
  const Table t = csv("--point 0,1,0");
  ASSERT_EQ(t.rows.size(), 1u) << out;
  EXPECT_EQ(t.header, (std::vector<std::string>{"x", "y", "z", "u", "v", "w", "q", "status", "reason"}));
  EXPECT_EQ(t.number(0, "u"), 0.25);
  EXPECT_EQ(t.number(0, "v"), 0.5);
  EXPECT_EQ(t.number(0, "w"), 0.0);
  EXPECT_EQ(t.number(0, "q"), 1.0);
  EXPECT_EQ(t.text(0, "status"), "ok");
  EXPECT_EQ(t.text(0, "reason"), "");
  EXPECT_EQ(out, "x,y,z,u,v,w,q,status,reason\n0,1,0,0.25,0.5,0,1,ok,\"\"\n");
}

TEST_F(EvalCli, SphereSeamPoleAndCentreHaveTheirStatuses) {
  const CliRun r = eval("--point 1,0,0 --point 0,0,2 --point 0,0,0 --point 0,-3,0");
  ASSERT_EQ(r.status, 0) << r.err;
  const Table t = parseCsv(out);
  ASSERT_EQ(t.rows.size(), 4u) << out;
  EXPECT_EQ(t.text(0, "status"), "on-seam");
  EXPECT_EQ(t.number(0, "u"), 0.0);
  EXPECT_EQ(t.number(0, "v"), 0.5);
  EXPECT_NE(t.text(0, "reason").find("seam"), std::string::npos);
  EXPECT_EQ(t.text(1, "status"), "pole");
  EXPECT_EQ(t.number(1, "u"), 0.0);
  EXPECT_EQ(t.number(1, "v"), 1.0);
  EXPECT_NE(t.text(1, "reason").find("axis"), std::string::npos);
  EXPECT_EQ(t.text(2, "status"), "invalid");
  EXPECT_EQ(t.number(2, "u"), 0.0);
  EXPECT_EQ(t.number(2, "v"), 0.0);
  EXPECT_EQ(t.text(2, "reason"), "the point is the sphere's centre");
  EXPECT_EQ(t.number(3, "u"), 0.75);
  EXPECT_EQ(t.text(3, "status"), "ok");
  EXPECT_NE(r.err.find("uvtk eval: 4 points, 1 ok, 1 poles, 1 on seam, 1 invalid"), std::string::npos) << r.err;
}

TEST_F(EvalCli, CylinderGivesTurnFractionAndHeight) {
  const Table t = csv("--projector cylinder --point 0,1,0.375 --point 0,-2,5 --point -4,0,-1");
  ASSERT_EQ(t.rows.size(), 3u) << out;
  EXPECT_EQ(t.number(0, "u"), 0.25);
  EXPECT_EQ(t.number(0, "v"), 0.375);
  EXPECT_EQ(t.number(1, "u"), 0.75);
  EXPECT_EQ(t.number(1, "v"), 5.0);
  EXPECT_EQ(t.number(2, "u"), 0.5);
  EXPECT_EQ(t.number(2, "v"), -1.0);
}

TEST_F(EvalCli, PlaneGivesXAndY) {
  const Table t = csv("--projector plane --point 0.3,0.7,5");
  EXPECT_EQ(t.number(0, "u"), 0.3);
  EXPECT_EQ(t.number(0, "v"), 0.7);
  EXPECT_EQ(t.text(0, "status"), "ok");
}

TEST_F(EvalCli, ExplicitPlacementMovesAndScalesThePoint) {
  // p = (P - c)/s = (0, 2, 0)/2: the sphere's (0, 1, 0).
  const Table t = csv("--center 1,1,1 --scale 2 --point 1,3,1");
  EXPECT_EQ(t.number(0, "u"), 0.25);
  EXPECT_EQ(t.number(0, "v"), 0.5);
}

TEST_F(EvalCli, CubeDirectConventionGivesTheNotesExample) {
  // The English notes: (-0.2, 0.5, -0.84) selects -Z (face id 5) and maps to (0.38, 0.80). With the
  // centroid O-mapping the point is projected centrally onto the face z = -1: s = (x/|z| + 1)/2.
  const Table t = csv("--projector cube --omap centroid --cube-convention direct --cube-layout faces --point=-0.2,0.5,-0.84");
  ASSERT_EQ(t.rows.size(), 1u) << out;
  EXPECT_EQ(t.number(0, "w"), 5.0);
  EXPECT_NEAR(t.number(0, "u"), (-0.2 / 0.84 + 1) / 2, 1e-15);
  EXPECT_NEAR(t.number(0, "v"), (0.5 / 0.84 + 1) / 2, 1e-15);
  EXPECT_NEAR(t.number(0, "u"), 0.38, 0.005);
  EXPECT_NEAR(t.number(0, "v"), 0.80, 0.005);
  EXPECT_EQ(t.text(0, "status"), "ok");
  // Each face's id is the third column.
  const Table faces =
      csv("--projector cube --omap centroid --cube-layout faces --point 2,0,0 --point=-2,0.5,0 --point 0,3,0 "
          "--point=0,-3,0 --point 0,0,4 --point=0,0,-4");
  ASSERT_EQ(faces.rows.size(), 6u) << out;
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(faces.number(i, "w"), double(i)) << i;
}

TEST_F(EvalCli, ConventionNotesGivesTheNotesExampleByName) {
  // --convention notes stands for --cube-convention direct --fit none --omap centroid --cube-layout faces.
  const Table t = csv("--projector cube --convention notes --point=-0.2,0.5,-0.84");
  ASSERT_EQ(t.rows.size(), 1u) << out;
  EXPECT_EQ(t.number(0, "w"), 5.0);                   // -Z
  EXPECT_NEAR(t.number(0, "u"), 8.0 / 21.0, 1e-15);   // (1 - 0.2/0.84)/2 = 0.38095...
  EXPECT_NEAR(t.number(0, "v"), 67.0 / 84.0, 1e-15);  // (1 + 0.5/0.84)/2 = 0.797619...
  EXPECT_EQ(t.text(0, "status"), "ok");
  const std::string byName = out;
  csv("--projector cube --cube-convention direct --fit none --omap centroid --cube-layout faces "
      "--point=-0.2,0.5,-0.84");
  EXPECT_EQ(out, byName);
  // What it owns is refused beside it (exit 2).
  EXPECT_EQ(eval("--projector cube --convention notes --cube-convention gl --point 1,0,0").status, 2);
  EXPECT_EQ(eval("--projector cylinder --convention notes --point 1,0,0").status, 2);
}

TEST_F(EvalCli, TexgenSphereMapAndItsSingularPoint) {
  // Identity view, e = (0, 0, -5): u = (0, 0, -1); n = (0, 1, 1)/sqrt 2, n.u = -1/sqrt 2;
  // r = u - 2 n (n.u) = (0, 1, 0); m = 2 sqrt(0 + 1 + 1); (s, t) = (1/2, 1/(2 sqrt 2) + 1/2).
  const Table t = csv("--texgen sphere_map --point 0,0,-5 --normal 0,1,1");
  ASSERT_EQ(t.rows.size(), 1u) << out;
  EXPECT_EQ(t.header,
            (std::vector<std::string>{"x", "y", "z", "nx", "ny", "nz", "u", "v", "w", "q", "status", "reason"}));
  EXPECT_NEAR(t.number(0, "u"), 0.5, 1e-15);
  EXPECT_NEAR(t.number(0, "v"), 0.5 + 1 / (2 * std::sqrt(2.0)), 1e-15);
  EXPECT_EQ(t.text(0, "status"), "ok");
  // n perpendicular to the view ray: r = u = (0, 0, -1), m = 0: GL's s = t = 1/2, flagged.
  const Table singular = csv("--texgen sphere_map --point 0,0,-5 --normal 1,0,0");
  EXPECT_EQ(singular.text(0, "status"), "pole");
  EXPECT_EQ(singular.number(0, "u"), 0.5);
  EXPECT_EQ(singular.number(0, "v"), 0.5);
  EXPECT_NE(singular.text(0, "reason").find("m = 0"), std::string::npos);
}

TEST_F(EvalCli, TexgenObjectLinearIsThePlaneEquation) {
  const Table t = csv("--s object_linear:1,2,3,4 --point 0.5,-2,3 --point 1,1,1");
  ASSERT_EQ(t.rows.size(), 2u) << out;
  EXPECT_EQ(t.number(0, "u"), 0.5 - 4 + 9 + 4);  // s = x + 2y + 3z + 4
  EXPECT_EQ(t.number(1, "u"), 10.0);
  EXPECT_EQ(t.number(0, "v"), 0.0);  // t, r off: GL's current (0, 0, 0, 1)
  EXPECT_EQ(t.number(0, "w"), 0.0);
  EXPECT_EQ(t.number(0, "q"), 1.0);
  const Table q = csv("--s object_linear:1,0,0,0 --r object_linear:0,0,1,0 --q object_linear:0,0,0,2 --point 1,2,3");
  EXPECT_EQ(q.number(0, "w"), 3.0);  // r
  EXPECT_EQ(q.number(0, "q"), 2.0);  // undivided
}

TEST_F(EvalCli, BlenderConventionIsFittedToTheMesh) {
  // Bounding box (1, 2, 3)..(3, 6, 7): centre (2, 4, 5).
  writeText("box.obj", "v 1 2 3\nv 3 6 7\nv 1 6 3\nf 1 2 3\n");
  const Table t = csv("--convention blender --mesh " + path("box.obj") + " --point 3,4,5 --point 2,5,5");
  ASSERT_EQ(t.rows.size(), 2u) << out;
  EXPECT_EQ(t.number(0, "u"), 0.25);  // Blender: u = (1 - atan2(x, y)/pi)/2 of p = P - centre
  EXPECT_EQ(t.number(1, "u"), 0.5);
  EXPECT_EQ(t.number(0, "v"), 0.5);
}

TEST_F(EvalCli, WithAMeshAHitBeyondTwiceItsExtentIsOutOfRange) {
  // The unit square in z = 0, unplaced: the sensible box is [0, 1]^2 x {0}, centre (1/2, 1/2, 0),
  // half-extent 1/2, range R = 2 x 1/2 = 1 (docs/conventions.md §4). From p = (0.5, 0.5, 0.1) along
  // (1, 0, -0.01) the line meets z = 0 at x = 10.5: 10 from the centre, out of range; along
  // (1, 0, -1) at (0.6, 0.5).
  writeText("square.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const std::string options = "--projector plane --omap normal --fit none --point 0.5,0.5,0.1 ";
  const Table far = csv(options + "--normal 1,0,-0.01 --mesh " + path("square.obj"));
  ASSERT_EQ(far.rows.size(), 1u) << out;
  EXPECT_EQ(far.text(0, "status"), "invalid");
  EXPECT_NE(far.text(0, "reason").find("beyond"), std::string::npos) << out;
  const Table near = csv(options + "--normal 1,0,-1 --mesh " + path("square.obj"));
  EXPECT_NEAR(near.number(0, "u"), 0.6, 1e-15);
  EXPECT_NEAR(near.number(0, "v"), 0.5, 1e-15);
  // Without a mesh there is no box and no range check: the far hit is given as it is.
  const Table bare = csv(options + "--normal 1,0,-0.01");
  EXPECT_NEAR(bare.number(0, "u"), 10.5, 1e-12);
}

TEST_F(EvalCli, AssimpConventionIsFittedToTheMesh) {
  writeText("box.obj", "v 1 2 3\nv 3 6 7\nv 1 6 3\nf 1 2 3\n");
  const Table t = csv("--convention assimp --mesh " + path("box.obj") + " --point 3,4,5 --point 2,4,6");
  ASSERT_EQ(t.rows.size(), 2u) << out;
  EXPECT_EQ(t.number(0, "u"), 0.75);  // assimp: u = (atan2(x, z) + pi)/(2 pi) about the box centre
  EXPECT_EQ(t.number(1, "u"), 0.5);
}

// ---- Digits ---------------------------------------------------------------------------------

TEST_F(EvalCli, EveryNumberReadsBackAsTheSameDouble) {
  const double third = 1.0 / 3.0;
  const Table plane = csv("--projector plane --point " + g17(third) + "," + g17(2 * third) + ",0.1");
  EXPECT_TRUE(sameBits(plane.number(0, "u"), third)) << plane.text(0, "u");
  EXPECT_TRUE(sameBits(plane.number(0, "v"), 2 * third)) << plane.text(0, "v");
  EXPECT_EQ(plane.text(0, "u"), "0.33333333333333331");
  EXPECT_TRUE(sameBits(plane.number(0, "z"), 0.1));

  // Against the evaluator behind the point API, bit for bit.
  CLI::App app;
  cli::MappingArguments arguments;
  cli::addMappingOptions(app, arguments, param::Fit::None);
  app.parse(std::string("--projector sphere --omap normal"), false);
  const point::PointEvaluator evaluator(cli::resolveMapping(arguments), Affine3::Identity(), "test");
  const std::vector<point::Vector3> points = {{0.1, 0.2, 0.3}, {third, -0.7, 0.9}, {-1e-3, 2.5, -0.125}};
  const point::Vector3 normal = {0.3, -0.4, 0.5};
  std::string args = "--projector sphere --omap normal --normal 0.3,-0.4,0.5";
  for (const point::Vector3& p : points) args += " --point=" + g17(p[0]) + "," + g17(p[1]) + "," + g17(p[2]);
  const Table t = csv(args);
  ASSERT_EQ(t.rows.size(), points.size()) << out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const point::Result expected = evaluator.at(points[i], normal);
    EXPECT_TRUE(sameBits(t.number(i, "u"), expected.u)) << i << ": " << t.text(i, "u") << " " << g17(expected.u);
    EXPECT_TRUE(sameBits(t.number(i, "v"), expected.v)) << i << ": " << t.text(i, "v") << " " << g17(expected.v);
  }
}

// ---- Input on stdin -------------------------------------------------------------------------

TEST_F(EvalCli, CsvRowsWithAndWithoutHeader) {
  const Table plain = csv("", "# points\n0,1,0\n\n  \n-2,0,0\n");
  ASSERT_EQ(plain.rows.size(), 2u) << out;
  EXPECT_EQ(plain.number(0, "u"), 0.25);
  EXPECT_EQ(plain.number(1, "u"), 0.5);
  // A header names the columns in any order; normal_map's (s, t, r) is the unit normal.
  const Table named = csv("--texgen normal_map", "nz,ny,nx,x,y,z\r\n2,0,0,1,1,1\r\n0,-3,0,5,5,5\r\n");
  ASSERT_EQ(named.rows.size(), 2u) << out;
  EXPECT_EQ(named.header.at(3), "nx");
  EXPECT_EQ(named.number(0, "nz"), 2.0);
  EXPECT_EQ(named.number(0, "w"), 1.0);
  EXPECT_EQ(named.number(1, "v"), -1.0);
  EXPECT_EQ(named.number(1, "x"), 5.0);
  // Six columns without a header: x,y,z,nx,ny,nz.
  const Table six = csv("--texgen normal_map", "1,1,1,0,4,0\n");
  EXPECT_EQ(six.number(0, "v"), 1.0);
}

TEST_F(EvalCli, JsonLinesInAndOut) {
  const CliRun r = eval("--input json --format json --texgen normal_map",
                        "{\"p\": [1, 2, 3], \"n\": [0, 0, 5]}\n\n{\"p\": [\"nan\", 0, 0], \"n\": [1, 0, 0]}\n");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(out);
  std::vector<nlohmann::json> objects;
  for (std::string line; std::getline(lines, line);) objects.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(objects.size(), 2u) << out;
  EXPECT_EQ(objects[0].at("p"), nlohmann::json::array({1, 2, 3}));
  EXPECT_EQ(objects[0].at("n"), nlohmann::json::array({0, 0, 5}));
  EXPECT_EQ(objects[0].at("w").get<double>(), 1.0);
  EXPECT_EQ(objects[0].at("q").get<double>(), 1.0);
  EXPECT_EQ(objects[0].at("status"), "ok");
  EXPECT_EQ(objects[0].at("reason"), "");
  EXPECT_EQ(objects[1].at("p")[0], "nan");
  EXPECT_EQ(objects[1].at("status"), "invalid");
  EXPECT_EQ(objects[1].at("reason"), "the position is not finite");
  EXPECT_EQ(objects[1].at("u").get<double>(), 0.0);
}

TEST_F(EvalCli, NonFiniteInputIsAnInvalidRowNotAnError) {
  const CliRun r = eval("", "x,y,z\nnan,0,0\n1,-inf,2\n1e999,0,0\n0,1,0\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const Table t = parseCsv(out);
  ASSERT_EQ(t.rows.size(), 4u) << out;
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(t.text(i, "status"), "invalid") << i;
    EXPECT_EQ(t.text(i, "u"), "0") << i;
    EXPECT_EQ(t.text(i, "v"), "0") << i;
    EXPECT_EQ(t.text(i, "reason"), "the position is not finite") << i;
  }
  EXPECT_EQ(t.text(0, "x"), "nan");
  EXPECT_EQ(t.text(1, "y"), "-inf");
  EXPECT_EQ(t.text(2, "x"), "inf");
  EXPECT_EQ(out.find("nan", out.find('\n', out.find("nan"))), std::string::npos) << out;  // u, v never nan
  EXPECT_NE(r.err.find("4 points, 1 ok, 0 poles, 0 on seam, 3 invalid"), std::string::npos) << r.err;
}

TEST_F(EvalCli, PerRowEyeEqualsTheSameEyeGivenByOption) {
  const std::string eyes[2] = {"0,0,5", "3,-1,4"};
  const CliRun r = eval("--texgen sphere_map --normal 0,1,1", "x,y,z,ex,ey,ez\n0,0,0,0,0,5\n0.5,0.25,-1,3,-1,4\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const Table rows = parseCsv(out);
  ASSERT_EQ(rows.rows.size(), 2u) << out;
  EXPECT_EQ(rows.number(0, "ex"), 0.0);
  EXPECT_EQ(rows.number(1, "ex"), 3.0);
  EXPECT_NEAR(rows.number(0, "v"), 0.5 + 1 / (2 * std::sqrt(2.0)), 1e-15);  // as from (0, 0, -5) above
  const std::string points[2] = {"0,0,0", "0.5,0.25,-1"};
  for (int i = 0; i < 2; ++i) {
    const Table one = csv("--texgen sphere_map --normal 0,1,1 --point=" + points[i] + " --eye=" + eyes[i]);
    EXPECT_EQ(one.text(0, "u"), rows.text(std::size_t(i), "u")) << i;
    EXPECT_EQ(one.text(0, "v"), rows.text(std::size_t(i), "v")) << i;
  }
  // An eye that gives no view (at the default centre (0, 0, -1)) or is not finite: invalid rows.
  const Table bad = csv("--texgen sphere_map --normal 0,1,1", "x,y,z,ex,ey,ez\n0,0,0,0,0,-1\n0,0,0,nan,0,0\n");
  ASSERT_EQ(bad.rows.size(), 2u) << out;
  EXPECT_EQ(bad.text(0, "status"), "invalid");
  EXPECT_NE(bad.text(0, "reason").find("no view from this eye"), std::string::npos) << out;
  EXPECT_EQ(bad.text(1, "reason"), "the eye is not finite");
  EXPECT_EQ(bad.text(1, "ex"), "nan");
}

TEST_F(EvalCli, ReflectionTakesEachRowsEyeWithoutEyeOption) {
  // Plane, p = (0, 0, 1), N = -z (facing the plane), eye (1, 0, 0): V = (-1, 0, 1)/sqrt 2,
  // R = (-1, 0, -1)/sqrt 2; the ray p + tR meets z = 0 at t = sqrt 2, at (-1, 0, 0). From (0, 1, 0) at
  // (0, -1, 0).
  const Table t = csv("--projector plane --omap reflection --input json",
                      "{\"p\": [0, 0, 1], \"n\": [0, 0, -1], \"eye\": [1, 0, 0]}\n"
                      "{\"p\": [0, 0, 1], \"n\": [0, 0, -1], \"eye\": [0, 1, 0]}\n"
                      "{\"p\": [0, 0, 1], \"n\": [0, 0, -1], \"eye\": [0, 1, 0]}\n");
  ASSERT_EQ(t.rows.size(), 3u) << out;
  EXPECT_NEAR(t.number(0, "u"), -1.0, 1e-15);
  EXPECT_NEAR(t.number(0, "v"), 0.0, 1e-15);
  EXPECT_NEAR(t.number(1, "u"), 0.0, 1e-15);
  EXPECT_NEAR(t.number(1, "v"), -1.0, 1e-15);
  // With N = +z the reflected ray leaves the plane: it meets it only behind the point (§4).
  const Table behind = csv("--projector plane --omap reflection --input json",
                           "{\"p\": [0, 0, 1], \"n\": [0, 0, 1], \"eye\": [1, 0, 2]}\n");
  ASSERT_EQ(behind.rows.size(), 1u) << out;
  EXPECT_EQ(behind.text(0, "status"), "invalid");
  EXPECT_NE(behind.text(0, "reason").find("behind"), std::string::npos) << out;
  EXPECT_EQ(t.text(2, "v"), t.text(1, "v"));
  // A row without an eye then has none to use.
  const CliRun r =
      eval("--projector plane --omap reflection --input json",
           "{\"p\": [0, 0, 1], \"n\": [0, 0, 1], \"eye\": [1, 0, 2]}\n{\"p\": [0, 0, 1], \"n\": [0, 0, 1]}\n");
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find("<stdin>:2: error: expected an eye"), std::string::npos) << r.err;
}

// ---- Agreement with `uvtk map` --------------------------------------------------------------

TEST_F(EvalCli, AgreesWithMapOnTheIcosphereBitForBit) {
  const std::string mesh = std::string(UVTK_SOURCE_DIR) + "/meshes/icosphere.obj";
  ASSERT_EQ(uvtk("map " + mesh + " --projector sphere --fit none --seam none --pole none -o " + path("out.obj")).status,
            0);
  const Mesh mapped = io::readMesh(path("out.obj")).mesh;
  const Mesh input = io::readMesh(mesh).mesh;
  std::string rows;
  for (const Vec3& p : input.positions) rows += g17(p.x()) + "," + g17(p.y()) + "," + g17(p.z()) + "\n";
  const Table t = csv("--projector sphere", rows);
  ASSERT_EQ(t.rows.size(), input.positions.size()) << out;
  ASSERT_EQ(mapped.triangles.size(), input.triangles.size());
  std::size_t compared = 0, poles = 0;
  for (std::size_t f = 0; f < mapped.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t vertex = std::size_t(mapped.triangles[f][std::size_t(k)]);
      if (t.text(vertex, "status") == "pole") {
        ++poles;
        continue;
      }
      const Vec3 vt = mapped.texcoords[std::size_t(mapped.cornerTexcoords[f][std::size_t(k)])];
      EXPECT_TRUE(sameBits(vt.x(), t.number(vertex, "u")))
          << vertex << ": " << g17(vt.x()) << " " << t.text(vertex, "u");
      EXPECT_TRUE(sameBits(vt.y(), t.number(vertex, "v")))
          << vertex << ": " << g17(vt.y()) << " " << t.text(vertex, "v");
      ++compared;
    }
  EXPECT_GT(compared, 3000u);
  EXPECT_GT(poles, 0u);  // (0, 0, +-1) are vertices of the icosphere
}

TEST_F(EvalCli, AgreesWithMapOnAFittedPlacementWithAutomaticSeam) {
  const std::string mesh = std::string(UVTK_SOURCE_DIR) + "/meshes/torus.obj";
  const std::string options = " --projector cylinder --fit pca --seam-place auto";
  ASSERT_EQ(uvtk("map " + mesh + options + " --seam none --pole none -o " + path("out.obj")).status, 0);
  const Mesh mapped = io::readMesh(path("out.obj")).mesh;
  const Mesh input = io::readMesh(mesh).mesh;
  std::string rows;
  for (const Vec3& p : input.positions) rows += g17(p.x()) + "," + g17(p.y()) + "," + g17(p.z()) + "\n";
  const CliRun r = eval(options + " --mesh " + mesh, rows);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("seam placed at"), std::string::npos) << r.err;
  const Table t = parseCsv(out);
  ASSERT_EQ(t.rows.size(), input.positions.size()) << out;
  std::size_t different = 0, compared = 0;
  for (std::size_t f = 0; f < mapped.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::size_t vertex = std::size_t(mapped.triangles[f][std::size_t(k)]);
      if (t.text(vertex, "status") == "pole") continue;
      const Vec3 vt = mapped.texcoords[std::size_t(mapped.cornerTexcoords[f][std::size_t(k)])];
      different += !sameBits(vt.x(), t.number(vertex, "u")) || !sameBits(vt.y(), t.number(vertex, "v"));
      ++compared;
    }
  EXPECT_EQ(different, 0u);
  EXPECT_GT(compared, 6800u);  // of 6912 corners; the PCA axis lies in the torus' plane and meets a few vertices
}

// ---- Errors ---------------------------------------------------------------------------------

TEST_F(EvalCli, AFittedPlacementWithoutAMeshIsAUsageError) {
  for (const std::string options : {"--fit bbox", "--fit pca", "--convention blender", "--convention assimp"}) {
    const CliRun r = eval(options + " --point 0,1,0 -o " + path("out.csv"));
    EXPECT_EQ(r.status, 2) << options;
    EXPECT_NE(r.err.find("--mesh"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("out.csv")));
  }
  const CliRun r = eval("--projector sphere --seam-place auto --point 0,1,0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--mesh"), std::string::npos) << r.err;
}

TEST_F(EvalCli, AMalformedRowNamesItsLineAndWritesNothing) {
  writeText("out.csv", "precious");
  const struct {
    std::string options, input, message;
  } cases[] = {
      {"", "0,1,0\n1,2\n", "<stdin>:2: error: expected 3 columns (x,y,z), found 2"},
      {"", "# c\nx,y,z\n1,abc,3\n", "<stdin>:3: error: expected a number in column 2 (y), found 'abc'"},
      {"", "x,y,w\n", "<stdin>:1: error: expected a number or a column name"},
      {"", "x,y,nx\n", "<stdin>:1: error: expected the columns x, y and z in the header, found no 'z'"},
      {"", "1,2,3,4\n", "<stdin>:1: error: expected 3, 6 or 9 columns"},
      {"", "0x10,0,0\n", "<stdin>:1: error: expected a number in column 1 (x), found '0x10'"},
      {"--input json", "{\"p\": [1, 2, 3]}\n{\"p\": [1, 2]}\n", "<stdin>:2: error: expected \"p\" to be an array"},
      {"--input json", "{\"p\": [1, 2, 3]\n", "<stdin>:1: error: expected a JSON object"},
      {"--input json", "{\"q\": [1, 2, 3]}\n", "<stdin>:1: error: expected the keys p, n and eye, found \"q\""},
      {"", "x,y,z,ex,ey,ez\n1,2,3,0,0,5\n", "<stdin>:2: error: expected no eye"},
  };
  for (const auto& c : cases) {
    const CliRun r = eval(c.options + " -o " + path("out.csv"), c.input);
    EXPECT_EQ(r.status, 3) << c.input;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.input << "\n" << r.err;
    EXPECT_EQ(readText(path("out.csv")), "precious");
  }
  for (const auto& entry : fs::directory_iterator(dir_))  // no temporary left behind
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST_F(EvalCli, BadOptionsAreUsageErrors) {
  const std::string cases[] = {
      "--point 1,2",                                  // two numbers
      "--point 1,2,3 --normal 0,0,1 --normal 0,1,0",  // two normals for one point
      "--point 1,2,3 --input json",                   // --input describes stdin
      "--omap normal --point 1,2,3",                  // the mapping reads a normal, none given
      "--texgen sphere_map --mesh x.obj --point 1,2,3",
      "--texgen sphere_map --axis x --point 1,2,3",  // a projector option with texgen
  };
  for (const std::string& c : cases) EXPECT_EQ(eval(c).status, 2) << c;
}

TEST_F(EvalCli, OutputFileIsWrittenWithTheSameText) {
  ASSERT_EQ(eval("--point 0,1,0").status, 0);
  const std::string printed = out;
  ASSERT_EQ(eval("--point 0,1,0 -o " + path("o.csv")).status, 0);
  EXPECT_EQ(out, "");
  EXPECT_EQ(readText(path("o.csv")), printed);
}

TEST_F(EvalCli, HelpDescribesEverything) {
  ASSERT_EQ(shell(std::string(UVTK_BINARY) + " eval --help > " + path("help.txt")).status, 0);
  const std::string help = readText(path("help.txt"));
  for (const char* word : {"--point", "--normal", "--input", "--format", "--mesh", "--output", "--projector",
                           "--texgen", "--convention", "ex,ey,ez", "on-seam", "invalid", "pole", "%.17g", "<stdin>"})
    EXPECT_NE(help.find(word), std::string::npos) << word;
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
