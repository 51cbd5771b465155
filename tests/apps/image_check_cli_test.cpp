// `uvtk check --image` as a user runs it: a picture made by `uvtk render` passes with the options
// it was made with (projector, texgen, the file's UVs under an explicit camera); the same picture
// with a block of pixels changed, or drawn half a texel off, fails with exit status 1 and an error
// mask that marks the changed pixels; a shot of another size is an input error naming both sizes;
// the options of one mode are usage errors in the other, and nothing is written then.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test.h"
#include "io/image_io.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

using nlohmann::json;

class ImageCheckCli : public CliTest {
 protected:
  // `uvtk check ARGUMENTS` with stdout kept in out.txt.
  CliRun check(const std::string& arguments) const {
    return shell(std::string(UVTK_BINARY) + " check " + arguments + " > " + path("out.txt"));
  }
  std::string out() const { return readText(path("out.txt")); }

  // `uvtk render MESH SCENE -o NAME`: the shot.
  std::string render(const std::string& mesh, const std::string& scene, const std::string& name) const {
    const CliRun r = uvtk("render " + mesh + " " + scene + " -o " + path(name));
    EXPECT_EQ(r.status, 0) << r.err;
    return path(name);
  }

  static bool red(const Image& mask, int x, int row) {
    return mask.at(x, row, 0) == 1.0f && mask.at(x, row, 1) == 0.0f && mask.at(x, row, 2) == 0.0f;
  }
};

const std::string kScene = "--projector sphere --filter linear_mipmap_linear --texture checker:64:8 --size 160x120";

TEST_F(ImageCheckCli, ItsOwnPicturePassesAndWritesTheMaskAndRecord) {
  const std::string shot = render(kIcosphere, kScene, "shot.png");
  const CliRun r = check(kIcosphere + " " + kScene + " --image " + shot + " --error-mask " + path("mask.png") +
                         " --json " + path("check.json"));
  EXPECT_EQ(r.status, 0) << r.err << out();
  EXPECT_NE(out().find("pixels: 19200 checked, 0 invalid"), std::string::npos) << out();
  EXPECT_NE(out().find("uvtk check: PASS\n"), std::string::npos) << out();
  const json record = json::parse(readText(path("check.json")));
  EXPECT_EQ(record["status"], "pass");
  EXPECT_EQ(record["invalid"], 0);
  EXPECT_EQ(record["checked"], 160 * 120);
  EXPECT_EQ(record["precision"]["color_bits"], 6);  // 8 - 2 for a *_mipmap_linear filter
  EXPECT_EQ(record["precision"]["lod_bits"], 6);  // dEQP's for GLES 3 filtering
  // The mask is the shot at a third: no pixel red, and a pixel's channel a third of the shot's.
  const Image mask = io::readImage(path("mask.png")).image;
  const Image picture = io::readImage(shot).image;
  ASSERT_EQ(mask.width, 160);
  for (int row = 0; row < mask.height; ++row)
    for (int x = 0; x < mask.width; ++x) {
      ASSERT_FALSE(red(mask, x, row)) << x << ", " << row;
      EXPECT_NEAR(mask.at(x, row, 1), picture.at(x, row, 1) / 3, 0.5 / 255 + 1e-6);
    }
}

TEST_F(ImageCheckCli, TexgenAndTheFilesUvsUnderAnExplicitCameraPassToo) {
  const std::string texgen = "--texgen object_linear --filter linear --texture checker:32:4 --size 96x96";
  EXPECT_EQ(check(kIcosphere + " " + texgen + " --image " + render(kIcosphere, texgen, "texgen.png")).status, 0)
      << out();
  // The file's UVs; --eye, --center, --up and --fovy are the camera's, as in `uvtk render`.
  const CliRun mapped = uvtk("map " + kIcosphere + " --projector cylinder -o " + path("mapped.obj"));
  ASSERT_EQ(mapped.status, 0) << mapped.err;
  const std::string camera = "--eye 0.5,2.5,2 --center 0,0,0.1 --up 0,0,1 --fovy 40 --size 96x72 --filter nearest";
  const std::string shot = render(path("mapped.obj"), camera, "camera.png");
  EXPECT_EQ(check(path("mapped.obj") + " " + camera + " --image " + shot).status, 0) << out();
  // Another field of view is another picture.
  const std::string wider = "--eye 0.5,2.5,2 --center 0,0,0.1 --up 0,0,1 --fovy 44 --size 96x72 --filter nearest";
  EXPECT_EQ(check(path("mapped.obj") + " " + wider + " --image " + shot).status, 1) << out();
}

TEST_F(ImageCheckCli, ChangedPixelsFailAndTheMaskMarksExactlyThose) {
  const std::string shot = render(kIcosphere, kScene, "shot.png");
  Image picture = io::readImage(shot).image;
  // A 10 x 6 block in the middle of the sphere, each channel moved by a quarter (c -> c -+ 1/4).
  for (int row = 57; row < 63; ++row)
    for (int x = 75; x < 85; ++x)
      for (int c = 0; c < 3; ++c) picture.at(x, row, c) += picture.at(x, row, c) < 0.5f ? 0.25f : -0.25f;
  io::writeImage(path("changed.png"), picture, io::PixelType::UInt8);
  const CliRun r = check(kIcosphere + " " + kScene + " --image " + path("changed.png") + " --error-mask " +
                         path("mask.png") + " --json " + path("check.json"));
  EXPECT_EQ(r.status, 1) << r.err << out();
  EXPECT_NE(out().find("uvtk check: FAIL ("), std::string::npos) << out();
  const json record = json::parse(readText(path("check.json")));
  EXPECT_EQ(record["status"], "fail");
  EXPECT_GE(record["invalid"].get<int>(), 55);  // nearly all: a quarter is far beyond the tolerances
  EXPECT_LE(record["invalid"].get<int>(), 60);
  EXPECT_EQ(record["first_invalid"][0]["row"], 57);
  const Image mask = io::readImage(path("mask.png")).image;
  int marked = 0;
  for (int row = 0; row < mask.height; ++row)
    for (int x = 0; x < mask.width; ++x)
      if (red(mask, x, row)) {
        ++marked;
        EXPECT_TRUE(row >= 57 && row < 63 && x >= 75 && x < 85) << x << ", " << row;
      }
  EXPECT_EQ(marked, record["invalid"].get<int>());
}

TEST_F(ImageCheckCli, HalfATexelOffFails) {
  // --uv-offset half a texel of the 64-texel checker: the shot's (u, v) are shifted.
  const std::string shot = render(kIcosphere, kScene + " --uv-offset 0.0078125,0", "shifted.png");
  EXPECT_EQ(check(kIcosphere + " " + kScene + " --image " + shot).status, 1) << out();
  EXPECT_NE(out().find(" invalid ("), std::string::npos);
}

TEST_F(ImageCheckCli, AShotOfAnotherSizeIsAnInputErrorNamingBoth) {
  const std::string shot = render(kIcosphere, kScene, "shot.png");
  const CliRun r = check(kIcosphere + " --projector sphere --size 150x120 --image " + shot + " --error-mask " +
                         path("mask.png"));
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("the shot is 160x120 pixels, the rendering 150x120"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(path("mask.png")));
  EXPECT_EQ(check(kIcosphere + " --projector sphere --image " + path("missing.png")).status, 3);
}

TEST_F(ImageCheckCli, OptionsOfTheOtherModeAreUsageErrors) {
  const std::string shot = render(kIcosphere, kScene, "shot.png");
  const std::string image = " --size 160x120 --image " + shot + " --error-mask " + path("mask.png");
  const auto usage = [&](const std::string& arguments, const std::string& message) {
    const CliRun r = check(kIcosphere + " " + arguments);
    EXPECT_EQ(r.status, 2) << arguments << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("mask.png"))) << arguments;
  };
  usage("--projector sphere --tolerance 0.1" + image, "--tolerance goes with the UV comparison, not --image");
  usage("--projector sphere --view " + path("view.png") + image, "--view goes with the UV comparison");
  usage("--projector sphere --filter linear", "--filter goes with --image");
  usage("--projector sphere --coord-bits 12", "--coord-bits goes with --image");
  usage("--projector sphere --coord-bits 0" + image, "coord-bits: expected 1 to 30 bits, got 0");
  usage("--projector sphere --color-bits 17" + image, "color-bits: expected 1 to 16 bits, got 17");
  usage("--texgen normal_map --texture cube" + image, "a cube-map texture is not supported");
  usage("--projector triplanar" + image, "triplanar");
  usage("--projector sphere --wrap u" + image, "--wrap: 'u' is not one of: repeat, clamp_to_edge, mirrored_repeat");
  usage("--projector camera --eye 0,0,3" + image, "--projector camera is not supported");
  usage("--projector sphere --derivatives quad-coarse" + image, "--derivatives does not go with --image");
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
