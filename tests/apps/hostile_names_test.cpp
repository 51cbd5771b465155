// Names and files the user never named, as the hostile-input audit of issue 48 met them: paths that
// are not UTF-8 in every JSON uvtk writes (and read back by merge-reports), output names up to the
// 255 bytes a folder entry holds, a .gltf whose .bin is a FIFO or a device, a glTF naming a huge
// buffer file, a small GLB whose primitives share one accessor until the mesh would not fit, and a
// small PNG that decodes to more memory than there is.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;
using nlohmann::json;

class HostileNames : public CliTest {
 protected:
  std::string cube() const { return std::string(UVTK_MESHES_DIR) + "/cube.obj"; }
  static std::size_t lines(const std::string& text) { return std::size_t(std::count(text.begin(), text.end(), '\n')); }
  // The shell's quoting of a path of any bytes but NUL and '.
  static std::string quoted(const std::string& path) { return "'" + path + "'"; }
};

// Python's os.fsdecode of a name: each byte that is not part of valid UTF-8 as U+DC80..U+DCFF.
TEST_F(HostileNames, APathThatIsNotUtf8IsWrittenAsSurrogateEscapesInEveryJson) {
  const std::string input = path("in\xff.obj"), output = path("out\xfe.obj");
  fs::copy_file(cube(), input);
  const CliRun map = uvtk("map " + quoted(input) + " -o " + quoted(output) + " --json " + path("map.json") + " --quiet");
  ASSERT_EQ(map.status, 0) << map.err;
  const std::string text = readText(path("map.json"));
  EXPECT_NE(text.find("in\\udcff.obj"), std::string::npos) << text;
  EXPECT_NE(text.find("out\\udcfe.obj"), std::string::npos);

  const CliRun report = uvtk("report " + quoted(output) + " --json " + path("report.json") + " --html " +
                             quoted(path("page\xfd.html")) + " --quiet");
  ASSERT_EQ(report.status, 0) << report.err;
  EXPECT_NE(readText(path("report.json")).find("out\\udcfe.obj"), std::string::npos);
  EXPECT_TRUE(fs::exists(path("page\xfd.html")));

  const CliRun render = uvtk("render " + quoted(output) + " -o " + quoted(path("p\xfc.png")) + " --json " +
                             path("render.json") + " --quiet");
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_NE(readText(path("render.json")).find("p\\udcfc.png"), std::string::npos);

  // merge-reports reads the escapes back as the bytes they stand for.
  const CliRun merge = uvtk("merge-reports " + path("report.json") + " -o " + path("merged.json"));
  ASSERT_EQ(merge.status, 0) << merge.err;
  const std::string merged = readText(path("merged.json"));
  EXPECT_NE(merged.find("out\\udcfe.obj"), std::string::npos) << merged.substr(0, 400);
}

TEST_F(HostileNames, OutputNamesUpToTheLongestAFolderHoldsAreWritten) {
  for (const std::size_t length : {240u, 250u, 255u}) {
    const std::string name = std::string(length - 4, 'n') + ".obj";
    const CliRun run = uvtk("map " + cube() + " -o " + path(name) + " --json " + path(std::string(length - 5, 'j') + ".json") +
                            " --quiet");
    EXPECT_EQ(run.status, 0) << length << ": " << run.err;
    EXPECT_TRUE(fs::exists(path(name))) << length;
  }
  // A .gltf of 255 bytes: its .bin is shorter and both are published.
  const std::string gltf = std::string(250, 'g') + ".gltf";
  const CliRun run = uvtk("map " + cube() + " -o " + path(gltf) + " --quiet");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(path(std::string(250, 'g') + ".bin")));
}

TEST_F(HostileNames, ASceneOutputOfTheLongestNameRunsEveryStageAndIsWritten) {
  const std::string name = std::string(251, 's') + ".obj";
  const json scene = {{"meshes",
                       {{{"name", "cube"},
                         {"path", cube()},
                         {"mappings", {{{"kind", "projector"}, {"name", "m"}, {"projector", "atlas"}}}}}}},
                      {"outputs", {{{"kind", "obj"}, {"mapping", "m"}, {"path", name}}}}};
  writeText("scene.json", scene.dump(2));
  const CliRun run = uvtk("run " + path("scene.json") + " --output-dir " + dir_.string() + " --quiet");
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_TRUE(fs::exists(path(name)));
}

// The .bin beside a .gltf is a name the user did not give: a FIFO there would hang the write, a
// device would swallow the buffer and leave a glTF that cannot be read back.
TEST_F(HostileNames, AGltfWhoseBufferNameIsAFifoOrADeviceIsRefusedBeforeAnyWork) {
  ASSERT_EQ(::mkfifo(path("pipe.bin").c_str(), 0644), 0);
  const CliRun fifo = shell("timeout 60 " + std::string(UVTK_BINARY) + " map " + cube() + " -o " + path("pipe.gltf") + " --quiet");
  EXPECT_EQ(fifo.status, 4) << fifo.err;
  EXPECT_EQ(fifo.err, path("pipe.gltf") + ": error: cannot write: its buffer goes to " + path("pipe.bin") +
                          ", which is a FIFO, not a file (a .glb output holds its buffer inside)\n");
  EXPECT_FALSE(fs::exists(path("pipe.gltf")));

  fs::create_symlink("/dev/null", path("null.bin"));
  const CliRun device = uvtk("map " + cube() + " -o " + path("null.gltf") + " --quiet");
  EXPECT_EQ(device.status, 4) << device.err;
  EXPECT_NE(device.err.find("which is a character device"), std::string::npos) << device.err;
  EXPECT_EQ(lines(device.err), 1u);
  EXPECT_FALSE(fs::exists(path("null.gltf")));
  EXPECT_TRUE(fs::is_symlink(path("null.bin")));
}

TEST_F(HostileNames, ABufferFileLargerThanItsByteLengthIsRefusedUnread) {
  // 72 bytes of glTF naming a sparse 2 GiB file: refused by its size, not after reading it.
  writeText("big.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"big.bin"}]})");
  { std::ofstream(path("big.bin"), std::ios::binary) << "x"; }
  fs::resize_file(path("big.bin"), std::uintmax_t(2) << 30);
  // Under 1 GB of address space, so that reading the file first would fail (not under the
  // sanitizers, which reserve terabytes: there the message alone is checked).
  const std::string limit = kAddressSanitized ? "" : "ulimit -v 1000000; ";
  const CliRun run = shell(leakCheckOff() + limit + std::string(UVTK_BINARY) + " map " + path("big.gltf") + " -o " +
                           path("out.obj") + " --quiet");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(run.err, path("big.gltf") + ": /buffers/0: error: expected 36 bytes (its byteLength) in 'big.bin', found 2147483648\n");
}

TEST_F(HostileNames, PrimitivesSharingOneAccessorAreCountedExpandedAgainstTheMemoryAvailable) {
  if (kAddressSanitized) GTEST_SKIP() << "the sanitizers reserve terabytes of address space, which ulimit -v forbids";
  // A 40 KB GLB: 3300 positions read by 3000 primitives, 9.9 million vertices once expanded (1.2 GiB
  // to map), under a 800 MB address space.
  std::string bin;
  for (int i = 0; i < 3300; ++i)
    for (const float c : {float(i % 17), float(i % 29), float(i % 31)}) bin.append(reinterpret_cast<const char*>(&c), 4);
  json primitives = json::array();
  for (int p = 0; p < 3000; ++p) primitives.push_back({{"attributes", {{"POSITION", 0}}}});
  const json document = {{"asset", {{"version", "2.0"}}},
                         {"scene", 0},
                         {"scenes", {{{"nodes", {0}}}}},
                         {"nodes", {{{"mesh", 0}}}},
                         {"meshes", {{{"primitives", primitives}}}},
                         {"buffers", {{{"byteLength", bin.size()}}}},
                         {"bufferViews", {{{"buffer", 0}, {"byteLength", bin.size()}}}},
                         {"accessors",
                          {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3300}, {"type", "VEC3"},
                            {"min", {0, 0, 0}}, {"max", {16, 28, 30}}}}}};
  std::string text = document.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + text.size() + 8 + bin.size())) + u32(std::uint32_t(text.size())) +
                          "JSON" + text + u32(std::uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
  writeText("shared.glb", glb);
  const CliRun run = shell("ulimit -v 800000; " + std::string(UVTK_BINARY) + " map " + path("shared.glb") + " -o " +
                           path("out.obj") + " --quiet");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(run.err.find(path("shared.glb") + ": error: its scene holds 9900000 vertices and indices once instanced, "
                                               "which need about 1.2 GiB of memory, more than the "),
            0u)
      << run.err;
  EXPECT_EQ(lines(run.err), 1u);
  EXPECT_FALSE(fs::exists(path("out.obj")));
}

TEST_F(HostileNames, ATextureThatDecodesToMoreThanTheMemoryAvailableIsRefusedFromItsHeader) {
  if (kAddressSanitized) GTEST_SKIP() << "the sanitizers reserve terabytes of address space, which ulimit -v forbids";
  // 11000 x 11000 black RGB in a 350 KB PNG: within the 2^27-pixel limit, 1.4 GiB as float.
  const std::uint32_t side = 11000;
  const std::string row = std::string(1 + 3 * side, '\0');  // filter byte 0, then the pixels
  std::string raw;
  for (std::uint32_t y = 0; y < side; ++y) raw += row;
  uLongf packedSize = compressBound(uLong(raw.size()));
  std::string packed(packedSize, '\0');
  ASSERT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize, reinterpret_cast<const Bytef*>(raw.data()),
                      uLong(raw.size()), 9),
            Z_OK);
  packed.resize(packedSize);
  const auto be32 = [](std::uint32_t v) {
    return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
  };
  const auto chunk = [&](const std::string& type, const std::string& data) {
    const std::string body = type + data;
    return be32(std::uint32_t(data.size())) + body +
           be32(std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
  };
  const std::string header = be32(side) + be32(side) + std::string{8, 2, 0, 0, 0};
  writeText("bomb.png", "\x89PNG\r\n\x1a\n" + chunk("IHDR", header) + chunk("IDAT", packed) + chunk("IEND", ""));
  const CliRun run = shell("ulimit -v 1500000; " + std::string(UVTK_BINARY) + " render " + cube() +
                           " --projector sphere --texture " + path("bomb.png") + " -o " + path("r.png") + " --quiet");
  EXPECT_EQ(run.status, 3) << run.err;
  EXPECT_EQ(run.err.find(path("bomb.png") + ": error: image is 11000 x 11000 x 3 channels, 1.4 GiB as float, more than the "), 0u)
      << run.err;
  EXPECT_EQ(lines(run.err), 1u);
  EXPECT_FALSE(fs::exists(path("r.png")));
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
