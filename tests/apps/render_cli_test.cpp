// `uvtk render` as a user runs it: images and AOVs that read back, every texture-coordinate
// source, and clear errors with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "apps/cli_test.h"
#include "io/image_io.h"
#include "io/obj_writer.h"
#include "meshes/generators.h"

namespace uvtk {
namespace {

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
  const CliRun r = uvtk("render " + path("plane.obj") +
                        " --texgen object_linear --eye 0,0,2 --ortho -1,1,-1,1 --size 40x40 --aov uv,face -o " +
                        path("out.png"));
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
  const CliRun r = uvtk("render " + path("plane.obj") + " --texgen object_linear --texmatrix 0.5,0,0,0,0,0.5,0,0,0,0,1,0,0.5,0.5,0,1" +
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

}  // namespace
}  // namespace uvtk
