// `uvtk render --view checker --checks N`: N checks across the unit square, and the option's range.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/cli_test.h"
#include "io/image_io.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

class RenderChecks : public CliTest {
 protected:
  // The quad [-1, 1]^2 in z = 0 with vt over [0, 1]^2.
  std::string quad() const {
    return writeText("quad.obj",
                     "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                     "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
  }
  // Runs of equal 8-bit colour along `row`, background (black) left out.
  static int runs(const Image& image, int row) {
    int count = 0, last = -1;
    for (int x = 0; x < image.width; ++x) {
      const int grey = int(std::lround(image.at(x, row, 0) * 255));
      if (grey == 0) continue;
      if (grey != last) ++count;
      last = grey;
    }
    return count;
  }
};

TEST_F(RenderChecks, ChecksSetsTheCheckerViewsChecksAcross) {
  const std::string mesh = quad();
  for (int checks : {4, 16}) {
    const std::string out = path("checks" + std::to_string(checks) + ".png");
    const CliRun r = uvtk("render " + mesh + " --view checker --checks " + std::to_string(checks) +
                          " --view-dir 0,0,1 --size 128x128 -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    const Image image = io::readImage(out).image;
    EXPECT_EQ(runs(image, 67), checks);  // a row just below the middle: inside one row of checks
  }
  // The default is 16.
  const CliRun r = uvtk("render " + mesh + " --view checker --view-dir 0,0,1 --size 128x128 -o " + path("d.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(runs(io::readImage(path("d.png")).image, 67), 16);
}

TEST_F(RenderChecks, ChecksOutsideOneTo1024IsAUsageError) {
  const std::string mesh = quad();
  for (const char* checks : {"0", "1025", "-2"}) {
    const CliRun r = uvtk("render " + mesh + " --view checker --checks " + checks + " -o " + path("x.png"));
    EXPECT_EQ(r.status, 2) << checks << ": " << r.err;
    EXPECT_NE(r.err.find("--checks"), std::string::npos) << r.err;
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
