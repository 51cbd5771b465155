// `uvtk render` as a user runs it: images and AOVs that read back, every texture-coordinate
// source, and clear errors with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

class RenderCli : public CliTest {
 protected:
  void SetUp() override {
    CliTest::SetUp();
    io::writeObj(path("plane.obj"), meshes::planeGrid(8, 8, 2, 2), nullptr);
    io::writeObj(path("sphere.obj"), meshes::latLongSphere(32, 16), nullptr);
  }
  // The channel of an image by name (EXR files list channels alphabetically).
  static int channel(const Image& image, const std::string& name) {
    for (int c = 0; c < image.channels; ++c)
      if (image.channelNames[std::size_t(c)] == name) return c;
    return -1;
  }
  std::string bytes(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

TEST_F(RenderCli, RendersTheFilesOwnTexCoordsIntoAPngOfTheGivenSize) {
  ASSERT_EQ(uvtk("map " + path("plane.obj") + " --projector plane --fit bbox -o " + path("mapped.obj")).status, 0);
  const CliRun r = uvtk("render " + path("mapped.obj") + " --size 96x64 -o " + path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const io::ImageFile image = io::readImage(path("out.png"));
  EXPECT_EQ(image.image.width, 96);
  EXPECT_EQ(image.image.height, 64);
  EXPECT_EQ(image.image.channels, 3);
  EXPECT_NE(r.err.find("uvtk render: 96x64, 128 faces drawn"), std::string::npos) << r.err;
}

TEST_F(RenderCli, TexgenObjectLinearUnderAnOrthographicCameraGivesUEqualToX) {
  // The plane z = 0 seen from +z through glOrtho(-1, 1, -1, 1): pixel i's centre is at
  // x = -1 + 2 (i + 0.5) / 40, and OBJECT_LINEAR with GL's default s plane gives s = x.
  const CliRun r =
      uvtk("render " + path("plane.obj") +
           " --texgen object_linear --eye 0,0,2 --ortho -1,1,-1,1 --size 40x40 --aov uv,face -o " + path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const io::ImageFile aov = io::readImage(path("out.exr"));
  const int u = channel(aov.image, "u"), v = channel(aov.image, "v"), face = channel(aov.image, "face");
  ASSERT_GE(u, 0);
  ASSERT_GE(face, 0);
  for (int row = 0; row < 40; ++row)
    for (int i = 0; i < 40; ++i) {
      ASSERT_GE(aov.image.at(i, row, face), 0.0f);
      EXPECT_NEAR(aov.image.at(i, row, u), -1 + 2 * (i + 0.5) / 40, 1e-6);
      EXPECT_NEAR(aov.image.at(i, row, v), 1 - 2 * (row + 0.5) / 40, 1e-6);  // row 0 is the top
    }
}

TEST_F(RenderCli, PerPixelEvaluationOfALinearProjectorMatchesPerVertexInterpolation) {
  const std::string common = " --projector plane --eye 0.3,-0.4,2 --size 48x48 --aov uv,face ";
  ASSERT_EQ(uvtk("render " + path("plane.obj") + common + "-o " + path("vertex.png")).status, 0);
  const CliRun r = uvtk("render " + path("plane.obj") + common + "--uv per-pixel -o " + path("pixel.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Image a = io::readImage(path("vertex.exr")).image, b = io::readImage(path("pixel.exr")).image;
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  int covered = 0;
  for (int row = 0; row < 48; ++row)
    for (int x = 0; x < 48; ++x) {
      if (a.at(x, row, channel(a, "face")) < 0) continue;
      ++covered;
      EXPECT_NEAR(a.at(x, row, channel(a, "u")), b.at(x, row, channel(b, "u")), 1e-6);
      EXPECT_NEAR(a.at(x, row, channel(a, "v")), b.at(x, row, channel(b, "v")), 1e-6);
    }
  EXPECT_GT(covered, 500);
}

TEST_F(RenderCli, PerPixelSphereCoordinatesDifferFromInterpolatedOnesMostNearThePole) {
  // Seen from above the pole, interpolated u is wrong inside the pole fan; the exact one is not.
  const std::string common = " --projector sphere --view-dir 0,0,1 --size 64x64 --aov uv,face ";
  ASSERT_EQ(uvtk("render " + path("sphere.obj") + common + "-o " + path("vertex.png")).status, 0);
  ASSERT_EQ(uvtk("render " + path("sphere.obj") + common + "--uv per-pixel -o " + path("pixel.png")).status, 0);
  const Image a = io::readImage(path("vertex.exr")).image, b = io::readImage(path("pixel.exr")).image;
  const int u = channel(a, "u");
  // Exact u at pixel (x, row) on the unit sphere seen from +z is the azimuth of its centre.
  double centreError = 0.0, exactError = 0.0;
  for (int row = 28; row < 36; ++row)
    for (int x = 28; x < 36; ++x) {
      const double px = x + 0.5 - 32, py = 32 - row - 0.5;
      double azimuth = std::atan2(py, px) / (2 * kPi);
      azimuth -= std::floor(azimuth);
      const auto wrapped = [&](double value) {
        const double d = value - azimuth;
        return std::abs(d - std::round(d));
      };
      centreError = std::max(centreError, wrapped(a.at(x, row, u)));
      exactError = std::max(exactError, wrapped(b.at(x, row, u)));
    }
  EXPECT_LT(exactError, 1e-5);
  EXPECT_GT(centreError, 1e-2);
}

TEST_F(RenderCli, TheImageIsTheSameForOneAndTwoThreads) {
  const std::string common = " --projector sphere --texture uvgrid:256 --filter linear_mipmap_linear --env modulate ";
  ASSERT_EQ(uvtk("render " + path("sphere.obj") + common + "--threads 1 -o " + path("one.png")).status, 0);
  ASSERT_EQ(uvtk("render " + path("sphere.obj") + common + "--threads 2 -o " + path("two.png")).status, 0);
  EXPECT_EQ(bytes("one.png"), bytes("two.png"));
}

TEST_F(RenderCli, AnImageFileTextureIsReadWithItsTopRowAtVOne) {
  // A 2 x 2 texture, red on top, blue below, seen flat with nearest filtering.
  Image texture(2, 2, 3, 0.0f);
  texture.at(0, 0, 0) = texture.at(1, 0, 0) = 1.0f;
  texture.at(0, 1, 2) = texture.at(1, 1, 2) = 1.0f;
  io::writeImage(path("tex.png"), texture, io::PixelType::UInt8);
  const CliRun r = uvtk(
      "render " + path("plane.obj") + " --texgen object_linear --texmatrix 0.5,0,0,0,0,0.5,0,0,0,0,1,0,0.5,0.5,0,1" +
      " --eye 0,0,2 --ortho -1,1,-1,1 --size 8x8 --texture " + path("tex.png") + " -o " + path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Image image = io::readImage(path("out.png")).image;
  EXPECT_EQ(image.at(3, 1, 0), 1.0f);  // upper half red
  EXPECT_EQ(image.at(3, 6, 2), 1.0f);  // lower half blue
  EXPECT_EQ(image.at(3, 6, 0), 0.0f);
}

TEST_F(RenderCli, BadArgumentsAndInputsAreClearErrorsAndWriteNothing) {
  const std::string out = " -o " + path("out.png");
  CliRun r = uvtk("render " + path("plane.obj") + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("has no texture coordinates (vt): give --projector"), std::string::npos) << r.err;
  r = uvtk("render " + path("plane.obj") + " --projector plane --size 0x10" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--size: expected WxH"), std::string::npos) << r.err;
  r = uvtk("render " + path("plane.obj") + " --projector plane --texture checker:0" + out);
  EXPECT_EQ(r.status, 2);
  r = uvtk("render " + path("plane.obj") + " --projector plane --texgen sphere_map" + out);
  EXPECT_EQ(r.status, 2);
  r = uvtk("render " + path("plane.obj") + " --projector plane --texture " + path("missing.png") + out);
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("missing.png") + ": error: cannot open"), std::string::npos) << r.err;
  {
    std::ofstream bad(path("bad.obj"));
    bad << "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n";
  }
  r = uvtk("render " + path("bad.obj") + " --projector plane" + out);
  EXPECT_EQ(r.status, 3);
  EXPECT_NE(r.err.find(path("bad.obj") + ":3:"), std::string::npos) << r.err;
  r = uvtk("render " + path("plane.obj") + " --projector plane -o " + path("no/such/folder/out.png"));
  EXPECT_EQ(r.status, 4);
  EXPECT_FALSE(fs::exists(path("out.png")));
  EXPECT_EQ(std::distance(fs::directory_iterator(path("")), fs::directory_iterator()), 4);  // the inputs and stderr
}

// ---- cube maps and sphere maps (docs/conventions.md §7) ----

// NORMAL_MAP gives the eye-space normal, and the cube map looks it up: under glOrtho from +z the
// unit sphere's normal at a pixel is (x, y, sqrt(1 - x^2 - y^2)), so each covered pixel shows
// cubeindex's blue 40 (f + 1) of the face f of that direction's major axis (the centre +Z: 200).
TEST_F(RenderCli, NormalMapLooksUpTheCubeFaceOfTheEyeSpaceNormal) {
  const CliRun r = uvtk("render " + path("sphere.obj") +
                        " --texgen normal_map --texture cubeindex:16 --filter nearest --eye 0,0,4 --center 0,0,0 "
                        "--ortho -1.25,1.25,-1.25,1.25 --size 64x64 --aov cubeface -o " +
                        path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Image image = io::readImage(path("out.png")).image;
  const auto blue = [&](int x, int y) { return int(std::lround(image.at(x, y, 2) * 255)); };
  EXPECT_EQ(blue(32, 32), 200);
  int covered = 0, compared = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      if (blue(x, y) == 0) continue;  // the background
      ++covered;
      ASSERT_TRUE(blue(x, y) % 40 == 0 && blue(x, y) <= 240) << x << ", " << y << ": " << blue(x, y);
      const double px = -1.25 + 2.5 * (x + 0.5) / 64, py = 1.25 - 2.5 * (y + 0.5) / 64;
      if (px * px + py * py > 0.9) continue;  // near the silhouette the mesh is not the sphere
      const Vec3 n(px, py, std::sqrt(1 - px * px - py * py));
      Vec3 sorted = n.cwiseAbs();
      std::sort(sorted.data(), sorted.data() + 3);
      if (sorted[2] - sorted[1] < 0.1) continue;  // too near a face boundary to tell
      int axis = 0;
      n.cwiseAbs().maxCoeff(&axis);
      const int face = 2 * axis + (n[axis] < 0 ? 1 : 0);
      EXPECT_EQ(blue(x, y), 40 * (face + 1)) << x << ", " << y;
      ++compared;
    }
  EXPECT_GT(covered, 1500);
  EXPECT_GT(compared, 1000);
  const Image aov = io::readImage(path("out.exr")).image;
  const int cubeface = channel(aov, "cubeface");
  ASSERT_GE(cubeface, 0);
  EXPECT_EQ(aov.at(32, 32, cubeface), 4.0f);
  EXPECT_EQ(aov.at(0, 0, cubeface), -1.0f);  // the background
}

// Every pixel of a reflection-mapped sphere shows one of cube:64's colours (a face colour, full or
// with its channels halved) or the background.
TEST_F(RenderCli, ReflectionMapShowsOnlyTheCubeTexturesColours) {
  const CliRun r =
      uvtk("render " + path("sphere.obj") + " --texgen reflection_map --texture cube:64 --size 64x64 --json " +
           path("out.json") + " -o " + path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::set<std::array<int, 3>> colours = {{0, 0, 0}};
  for (const std::array<int, 3>& face : std::vector<std::array<int, 3>>{
           {255, 0, 0}, {0, 255, 255}, {0, 255, 0}, {255, 0, 255}, {0, 0, 255}, {255, 255, 0}}) {
    colours.insert(face);
    colours.insert({face[0] / 2, face[1] / 2, face[2] / 2});
  }
  const Image image = io::readImage(path("out.png")).image;
  int covered = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      std::array<int, 3> rgb;
      for (int c = 0; c < 3; ++c) rgb[std::size_t(c)] = int(std::lround(image.at(x, y, c) * 255));
      ASSERT_TRUE(colours.count(rgb)) << x << ", " << y << ": " << rgb[0] << " " << rgb[1] << " " << rgb[2];
      covered += rgb != std::array<int, 3>{0, 0, 0};
    }
  EXPECT_GT(covered, 1000);
  const nlohmann::json j = nlohmann::json::parse(bytes("out.json"));
  EXPECT_EQ(j["texture"]["kind"], "cube");
  EXPECT_EQ(j["texture"]["size"], 64);
  EXPECT_EQ(j["texture"]["seamless"], false);
  EXPECT_EQ(j["texture"]["name"], "cube:64");
}

// A file's vt s t r is a direction, as glTexCoord3 gives it: the file uvtk texgen writes draws as
// --texgen does under the same view.
TEST_F(RenderCli, AFilesVtLooksUpTheCubeMapAsADirection) {
  const std::string view = " --eye 0,0,4 --center 0,0,0 --up 0,1,0";
  ASSERT_EQ(uvtk("texgen " + path("sphere.obj") + " --mode normal_map" + view + " -o " + path("vt.obj")).status, 0);
  const std::string common = " --texture cubeindex:16 --size 48x48" + view + " -o ";
  CliRun r = uvtk("render " + path("vt.obj") + common + path("file.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  r = uvtk("render " + path("sphere.obj") + " --texgen normal_map" + common + path("texgen.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(bytes("file.png"), bytes("texgen.png"));
}

// A cross image cut into faces is the same cube map as its six faces given as files.
TEST_F(RenderCli, ACrossImageIsTheSameCubeMapAsItsSixFaces) {
  const int n = 8;
  Image cross(4 * n, 3 * n, 3);
  for (int y = 0; y < cross.height; ++y)
    for (int x = 0; x < cross.width; ++x)
      for (int c = 0; c < 3; ++c) cross.at(x, y, c) = float((x * 37 + y * 11 + c * 101) % 256) / 255.0f;
  io::writeImage(path("cross.png"), cross, io::PixelType::UInt8);
  // (column, row from the top) of +X -X +Y -Y +Z -Z in the cross
  const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};
  std::string faces;
  for (int f = 0; f < 6; ++f) {
    Image face(n, n, 3);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) face.at(x, y, c) = cross.at(cells[f][0] * n + x, cells[f][1] * n + y, c);
    const std::string name = path("face" + std::to_string(f) + ".png");
    io::writeImage(name, face, io::PixelType::UInt8);
    faces += (f ? "," : "") + name;
  }
  const std::string common = " --texgen reflection_map --size 48x48 --filter linear ";
  ASSERT_EQ(uvtk("render " + path("sphere.obj") + common + "--texture cubecross:" + path("cross.png") + " -o " +
                 path("a.png"))
                .status,
            0);
  ASSERT_EQ(
      uvtk("render " + path("sphere.obj") + common + "--texture cubefaces:" + faces + " -o " + path("b.png")).status,
      0);
  EXPECT_EQ(bytes("a.png"), bytes("b.png"));
}

// A cube map's faces wrap clamp_to_edge unless --wrap says otherwise; then it applies to each face,
// and LINEAR's texels beyond a face's edge come from its opposite edge under repeat.
TEST_F(RenderCli, ACubeMapClampsToEdgeUnlessWrapIsGiven) {
  const std::string common = " --texgen reflection_map --texture cube:8 --filter linear --size 48x48";
  for (const auto& [wrap, file] : std::vector<std::pair<std::string, std::string>>{
           {"", "default.png"}, {" --wrap clamp_to_edge", "clamp.png"}, {" --wrap repeat", "repeat.png"}}) {
    const CliRun r = uvtk("render " + path("sphere.obj") + common + wrap + " -o " + path(file));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  EXPECT_EQ(bytes("default.png"), bytes("clamp.png"));
  EXPECT_NE(bytes("default.png"), bytes("repeat.png"));
}

// The automatic camera looks from report's direction, z up (a mushroom under the cylinder
// projector showed only its cap from +z); near the z axis, and with an eye, y is up.
TEST_F(RenderCli, TheDefaultCameraIsReportsAndUpFollowsTheDirection) {
  io::writeObj(path("knot.obj"), meshes::torus(24, 8, 1.0, 0.3), nullptr);
  const std::string common = "render " + path("knot.obj") + " --projector sphere --size 48x48 -o ";
  const auto picture = [&](const std::string& name, const std::string& camera) {
    const CliRun r = uvtk(common + path(name) + camera);
    EXPECT_EQ(r.status, 0) << r.err;
    return bytes(name);
  };
  EXPECT_EQ(picture("default.png", ""), picture("report.png", " --view-dir 1,-1.5,0.8 --up 0,0,1"));
  EXPECT_NE(picture("default.png", ""), picture("yup.png", " --view-dir 1,-1.5,0.8 --up 0,1,0"));
  EXPECT_EQ(picture("top.png", " --view-dir 0,0.3,1"), picture("topy.png", " --view-dir 0,0.3,1 --up 0,1,0"));
  EXPECT_EQ(picture("eye.png", " --eye 3,-4,2"), picture("eyey.png", " --eye 3,-4,2 --up 0,1,0"));
}

// Views draw their own textures: the --texture an image would use is not read for them (it was read
// whole and checked, so a views-only render failed on a texture it never sampled).
TEST_F(RenderCli, ViewsDoNotReadTheTexture) {
  io::writeObj(path("cube.obj"), meshes::cube(1), nullptr);
  { std::ofstream(path("broken.png"), std::ios::binary) << "\x89PNG\r\n\x1a\nnot a png"; }
  const std::string common = "render " + path("cube.obj") + " --projector cube --texture " + path("broken.png");
  const CliRun views = uvtk(common + " --view checker,seams --size 64x64 -o " + path("views.png"));
  EXPECT_EQ(views.status, 0) << views.err;
  const CliRun picture = uvtk(common + " --size 64x64 -o " + path("picture.png"));
  EXPECT_EQ(picture.status, 3) << picture.err;
  EXPECT_NE(picture.err.find("broken.png"), std::string::npos) << picture.err;
}

// The cube projector's faces layout keeps each face's id as r: seen from two opposite corners,
// per vertex and per pixel, every face shows its own blue of cubeindex.
TEST_F(RenderCli, TheCubeProjectorsFacesLayoutLooksUpEachFace) {
  io::writeObj(path("cube.obj"), meshes::cube(2), nullptr);
  for (const char* uv : {"per-vertex", "per-pixel"}) {
    std::set<int> blues;
    for (const char* viewDir : {"1,1,1", "-1,-1,-1"}) {
      const CliRun r = uvtk("render " + path("cube.obj") + " --projector cube --cube-layout faces --texture cubeindex:16 --uv " +
                            uv + " --view-dir " + viewDir + " --size 48x48 -o " + path("out.png"));
      ASSERT_EQ(r.status, 0) << r.err;
      const Image image = io::readImage(path("out.png")).image;
      for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) blues.insert(int(std::lround(image.at(x, y, 2) * 255)));
    }
    // The background and faces +X -X +Y -Y +Z -Z.
    EXPECT_EQ(blues, (std::set<int>{0, 40, 80, 120, 160, 200, 240})) << uv;
  }
}

TEST_F(RenderCli, SphereMapTexgenLooksUpTheSphereMapChecker) {
  const CliRun r = uvtk("render " + path("sphere.obj") +
                        " --texgen sphere_map --texture spheremap:64 --eye 0,0,4 "
                        "--center 0,0,0 --size 64x64 -o " +
                        path("out.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Image image = io::readImage(path("out.png")).image;
  // Near the sphere's silhouette the reflection points behind: orange or blue checks.
  const Vec3 rim(image.at(32 + 19, 32, 0), image.at(32 + 19, 32, 1), image.at(32 + 19, 32, 2));
  EXPECT_TRUE(rim.isApprox(Vec3(1, 160 / 255.0, 0), 1e-3) || rim.isApprox(Vec3(0, 64 / 255.0, 160 / 255.0), 1e-3))
      << rim.transpose();
}

TEST_F(RenderCli, CubeMapMistakesAreUsageErrorsThatWriteNothing) {
  const std::string sphere = path("sphere.obj"), out = " -o " + path("out.png");
  io::writeImage(path("wide.png"), Image(30, 20, 3), io::PixelType::UInt8);  // not 4N x 3N
  std::string five;
  for (int f = 0; f < 5; ++f) {
    five += (f ? "," : "") + path("face" + std::to_string(f) + ".png");
    io::writeImage(path("face" + std::to_string(f) + ".png"), Image(4, 4, 3), io::PixelType::UInt8);
  }
  for (const auto& [arguments, message] : std::vector<std::pair<std::string, std::string>>{
           {" --texgen normal_map --texture checker:8 --seamless",
            "--seamless filters cube maps across their edges: 'checker:8' is 2D"},
           {" --projector sphere --texture cube:8",
            "a cube-map texture needs directions: --texgen, a file's vt, or --projector cube --cube-layout faces"},
           {" --projector cube --cube-layout cross --texture cube:8", "give the layout image as a 2D texture"},
           {" --texgen normal_map --texture cubefaces:" + five, "cubefaces:PX,NX,PY,NY,PZ,NZ (six image files)"},
           {" --texgen normal_map --texture cubecross:" + path("wide.png"), path("wide.png") + ": a 4 x 3"},
           {" --texgen normal_map --texture cubeindex:300", "expected cubeindex[:N] with 1 <= N <= 256"},
           {" --texgen normal_map --aov cubeface", "--aov cubeface: the texture 'checker:64:8' is 2D"}}) {
    const CliRun r = uvtk("render " + sphere + arguments + out);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(path("out.png")) || fs::exists(path("out.exr"))) << arguments;
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
