// The bad-input catalogue (tests/data/bad/, described in docs/robustness.md) run through the program as a user runs
// it: every entry gives its exit status and its exact one-line message, writes nothing, and leaves an existing
// output file as it was. The few valid entries (CRLF line endings, OBJ as people write it, a PLY with per-corner
// texcoords, a two-solid STL, a glTF with a data: URI buffer) are accepted, some with a warning. Inputs too large
// to commit, or that git cannot hold (a folder, an unreadable file), are generated in the scratch folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include "apps/cli_test.h"

namespace uvtk {
namespace {
namespace UVTK_TEST_FILE {

namespace fs = std::filesystem;

const std::string kCatalogueDir = std::string(UVTK_SOURCE_DIR) + "/tests/data/bad";
const std::string kCube = std::string(UVTK_SOURCE_DIR) + "/meshes/cube.obj";
const std::string kSentinel = "an earlier output, to be left alone\n";

enum class Command {
  kMap,            // uvtk map FILE --projector sphere -o OUT/out.obj
  kRun,            // uvtk run FILE --output-dir OUT (each scene writes out.obj)
  kRenderTexture,  // uvtk render cube.obj --projector sphere --texture FILE -o OUT/out.png
  kRenderMesh,     // uvtk render FILE --projector sphere -o OUT/out.png
};

enum class Source {
  kCatalogue,   // the file under tests/data/bad/
  kText,        // a file holding `text`
  kLongLine,    // "v 0 0 0 " and 200 MB of spaces on one line
  kDirectory,   // an empty folder
  kUnreadable,  // a file with mode 000
};

struct Entry {
  Command command;
  const char* file;  // relative to the catalogue; a generated input gets the same name in the scratch folder
  int status;
  // The whole of stderr without its newline, FILE standing for the input's path and DIR for its folder. For a
  // valid input (status 0), a warning line that stderr must hold, or nullptr for none.
  const char* message;
  Source source = Source::kCatalogue;
  const char* text = "";  // what a kText input holds
};

const Entry kEntries[] = {
    // OBJ
    {Command::kMap, "obj/empty.obj", 3, "FILE:1: error: expected at least one face, found end of file"},
    {Command::kMap, "obj/truncated-mid-vertex.obj", 3, "FILE:3: error: expected a z coordinate, found end of line"},
    {Command::kMap, "obj/truncated-mid-face.obj", 3, "FILE:6: error: expected at least 3 vertices in a face, found 2"},
    {Command::kMap, "obj/no-faces.obj", 3, "FILE:5: error: expected at least one face, found end of file"},
    {Command::kMap, "obj/index-zero.obj", 3, "FILE:4: error: expected a vertex index in 1..3, found '0'"},
    {Command::kMap, "obj/negative-index-out-of-range.obj", 3,
     "FILE:4: error: expected a vertex index in -3..-1, found '-4'"},
    {Command::kMap, "obj/index-past-end.obj", 3, "FILE:4: error: expected a vertex index in 1..3, found '4'"},
    {Command::kMap, "obj/coordinate-nan.obj", 3, "FILE:2: error: expected a finite number, found 'nan'"},
    {Command::kMap, "obj/coordinate-inf.obj", 3, "FILE:3: error: expected a finite number, found 'inf'"},
    {Command::kMap, "obj/coordinate-1e999.obj", 3, "FILE:2: error: expected a finite number, found '1e999'"},
    {Command::kMap, "obj/binary-garbage.obj", 3, "FILE:1: error: expected text, found byte 0x1A"},
    {Command::kMap, "obj/utf16-le-bom.obj", 3,
     "FILE:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kMap, "obj/utf16-be-bom.obj", 3,
     "FILE:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kMap, "obj/crlf.obj", 0, nullptr},
    {Command::kMap, "obj/vertex-five-numbers.obj", 3,
     "FILE:2: error: expected x y z, x y z w or x y z r g b, found 5 numbers"},
    // Valid, with a warning: what people write.
    {Command::kMap, "obj/bowtie.obj", 0,
     "FILE:5: warning: polygons that are not simple (self-intersecting, non-planar or of zero area): 1, the first "
     "here; triangulated as given, they may fold"},
    {Command::kMap, "obj/vertex-colours.obj", 0, "FILE: warning: vertex colours ignored: 4 vertices"},
    {Command::kMap, "obj/vp.obj", 0, "FILE: warning: vp lines (free-form parameter vertices) ignored: 2"},
    {Command::kMap, "obj/index-plus-sign.obj", 0, nullptr},
    {Command::kMap, "obj/long-line.obj", 3, "FILE:1: error: expected a line of at most 64 MiB, found a longer one",
     Source::kLongLine},
    // `uvtk map` takes a folder for a batch of meshes; `uvtk render` reads one mesh.
    {Command::kMap, "obj/directory.obj", 3,
     "FILE: error: expected mesh files (.obj, .off, .ply, .stl, .gltf, .glb) in the folder, found none",
     Source::kDirectory},
    {Command::kRenderMesh, "obj/directory.obj", 3, "FILE: error: cannot open: Is a directory", Source::kDirectory},
    {Command::kMap, "obj/unreadable.obj", 3, "FILE: error: cannot open: Permission denied", Source::kUnreadable},
    // OFF
    {Command::kMap, "off/empty.off", 3,
     "FILE:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found end of file"},
    {Command::kMap, "off/wrong-header.off", 3,
     "FILE:1: error: expected an OFF header (OFF, NOFF, COFF, CNOFF or NCOFF), found 'ply'"},
    {Command::kMap, "off/truncated-after-header.off", 3, "FILE:2: error: expected a vertex count, found end of file"},
    {Command::kMap, "off/truncated-mid-counts.off", 3,
     "FILE:2: error: expected an edge count (a non-negative integer), found end of line"},
    {Command::kMap, "off/truncated-mid-vertices.off", 3, "FILE:5: error: expected 4 vertices, found end of file"},
    {Command::kMap, "off/truncated-mid-faces.off", 3, "FILE:9: error: expected 3 vertex indices, found 2"},
    {Command::kMap, "off/counts-more-vertices.off", 3, "FILE:7: error: expected end of line, found '1'"},
    {Command::kMap, "off/counts-more-faces.off", 3, "FILE:11: error: expected 5 faces, found end of file"},
    {Command::kMap, "off/counts-fewer-vertices.off", 3,
     "FILE:6: error: expected a face vertex count of at least 3, found '0'"},
    {Command::kMap, "off/counts-fewer-faces.off", 3, "FILE:10: error: expected end of file, found '3'"},
    {Command::kMap, "off/counts-1e12-vertices.off", 3,
     "FILE:2: error: expected a vertex count of at most 2147483647, found '1000000000000'"},
    {Command::kMap, "off/counts-1e12-faces.off", 3,
     "FILE:2: error: expected a face count of at most 2147483647, found '1000000000000'"},
    {Command::kMap, "off/negative-index.off", 3, "FILE:6: error: expected a vertex index in 0..2, found '-1'"},
    {Command::kMap, "off/index-past-end.off", 3, "FILE:6: error: expected a vertex index in 0..2, found '3'"},
    {Command::kMap, "off/coordinate-nan.off", 3, "FILE:4: error: expected a finite number, found 'nan'"},
    {Command::kMap, "off/coordinate-inf.off", 3, "FILE:5: error: expected a finite number, found '-inf'"},
    {Command::kMap, "off/coordinate-1e999.off", 3, "FILE:4: error: expected a finite number, found '1e999'"},
    {Command::kMap, "off/binary-garbage.off", 3, "FILE:1: error: expected text, found byte 0x19"},
    {Command::kMap, "off/utf16-le-bom.off", 3,
     "FILE:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kMap, "off/utf16-be-bom.off", 3,
     "FILE:1: error: expected ASCII/UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kMap, "off/crlf.off", 0, nullptr},
    {Command::kMap, "off/bowtie.off", 0,
     "FILE:7: warning: polygons that are not simple (self-intersecting, non-planar or of zero area): 1, the first "
     "here; triangulated as given, they may fold"},
    {Command::kMap, "off/long-line.off", 3, "FILE:1: error: expected a line of at most 64 MiB, found a longer one",
     Source::kLongLine},
    {Command::kMap, "off/directory.off", 3,
     "FILE: error: expected mesh files (.obj, .off, .ply, .stl, .gltf, .glb) in the folder, found none",
     Source::kDirectory},
    {Command::kMap, "off/unreadable.off", 3, "FILE: error: cannot open: Permission denied", Source::kUnreadable},
    // PLY
    {Command::kMap, "ply/truncated-mid-vertex.ply", 3,
     "FILE: byte 197: error: expected 4 vertices, found 2 and end of file"},
    {Command::kMap, "ply/truncated-mid-face.ply", 3,
     "FILE: byte 248: error: expected 4 faces, found 2 and end of file"},
    {Command::kMap, "ply/counts-fewer-vertices.ply", 3, "FILE:14: error: expected end of line, found '1'"},
    {Command::kMap, "ply/index-past-end.ply", 3, "FILE:16: error: expected a vertex index in 0..3, found '4'"},
    {Command::kMap, "ply/negative-index.ply", 3, "FILE:15: error: expected a vertex index in 0..3, found '-1'"},
    {Command::kMap, "ply/face-two-corners.ply", 3,
     "FILE:15: error: expected a face of at least 3 corners, found a face of 2 (a line, not a face)"},
    {Command::kMap, "ply/coordinate-nan.ply", 3,
     "FILE: byte 185: error: expected a finite float for property 'y', found nan"},
    {Command::kMap, "ply/missing-end-header.ply", 3,
     "FILE:9: error: expected a header keyword (comment, obj_info, format, element, property or end_header), found "
     "'0'"},
    {Command::kMap, "ply/unknown-property-type.ply", 3,
     "FILE:6: error: expected a property type (char, uchar, short, ushort, int, uint, float, double, or int8 ... "
     "float64), found 'float16'"},
    {Command::kMap, "ply/trailing-bytes.ply", 3,
     "FILE: byte 269: error: expected end of file after the last element, found 4 more bytes"},
    {Command::kMap, "ply/obj-renamed.ply", 3,
     "FILE:1: error: expected 'ply' (the first line of a PLY file), found 'v 0 0 0'"},
    {Command::kMap, "ply/texcoord-wrong-length.ply", 3,
     "FILE:20: error: expected a texcoord list of 2 numbers per corner (6 for 3 corners), found 4"},
    {Command::kMap, "ply/texcoords-colours.ply", 0, "FILE: warning: vertex colours ignored: 4 vertices"},
    // STL
    {Command::kMap, "stl/empty.stl", 3, "FILE: error: expected an STL file, found an empty file"},
    {Command::kMap, "stl/truncated.stl", 3,
     "FILE: error: expected 284 bytes (84 + 50 a triangle) for the 4 triangles the binary header claims, found 254 "
     "bytes"},
    {Command::kMap, "stl/coordinate-nan.stl", 3, "FILE: byte 212: error: expected a finite number, found nan"},
    {Command::kMap, "stl/missing-endloop.stl", 3,
     "FILE:14: error: expected 'endloop' (a facet has 3 vertices), found 'endfacet'"},
    {Command::kMap, "stl/four-vertex-loop.stl", 3,
     "FILE:14: error: expected 'endloop' (a facet has 3 vertices), found 'vertex'"},
    {Command::kMap, "stl/bad-number.stl", 3, "FILE:6: error: expected a number, found '0,5'"},
    {Command::kMap, "stl/garbage-after-endsolid.stl", 3,
     "FILE:31: error: expected 'solid' or end of file, found 'thanks'"},
    {Command::kMap, "stl/two-solids-upper-case.stl", 0, nullptr},
    // glTF
    {Command::kMap, "gltf/truncated.glb", 3,
     "FILE: byte 588: error: expected 40 more bytes (the GLB header's length is 628), found end of file"},
    {Command::kMap, "gltf/wrong-length.glb", 3,
     "FILE: byte 628: error: expected 100 more bytes (the GLB header's length is 728), found end of file"},
    {Command::kMap, "gltf/bad-json.gltf", 3,
     "FILE:7: error: invalid JSON at column 9: syntax error while parsing object - unexpected string literal; "
     "expected '}'"},
    {Command::kMap, "gltf/missing-buffer.gltf", 3,
     "FILE: /buffers/0: error: cannot read the buffer file 'missing.bin': No such file or directory"},
    {Command::kMap, "gltf/buffer-too-short.gltf", 3,
     "FILE: /buffers/0/uri: error: expected base64 data of exactly its byteLength, found other data"},
    {Command::kMap, "gltf/index-past-end.gltf", 3,
     "FILE: /meshes/0/primitives/0/indices: error: expected vertex indices below 4 (the POSITION count), found 4 at "
     "element 8"},
    {Command::kMap, "gltf/mode-9.gltf", 3,
     "FILE: /meshes/0/primitives/0/mode: error: expected a primitive mode in 0..6, found 9"},
    {Command::kMap, "gltf/lines-only.gltf", 3,
     "FILE: error: expected at least one triangle primitive in the scene, found none (1 primitive of points or "
     "lines skipped)"},
    {Command::kMap, "gltf/sparse-accessor.gltf", 3,
     "FILE: /accessors/0/sparse: error: sparse accessors are not supported"},
    {Command::kMap, "gltf/draco-required.gltf", 3,
     "FILE: /extensionsRequired/0: error: the file requires the extension 'KHR_draco_mesh_compression', which uvtk "
     "does not read (it reads KHR_mesh_quantization; KHR_texture_transform moves no vertex)"},
    {Command::kMap, "gltf/accessor-outside-view.gltf", 3,
     "FILE: /accessors/0: error: expected its 5 elements of 12 bytes within bufferView 0 (48 bytes), found them past "
     "its end"},
    {Command::kMap, "gltf/position-inf.gltf", 3,
     "FILE: /accessors/0: error: expected finite numbers, found inf in element 1"},
    {Command::kMap, "gltf/node-cycle.gltf", 3,
     "FILE: /nodes/1/children/0: error: node 0 is reached a second time (a cycle, or a child of two parents); uvtk "
     "reads node trees"},
    {Command::kMap, "gltf/no-position.gltf", 3,
     "FILE: /meshes/0/primitives/0/attributes: error: expected a POSITION attribute, found none"},
    {Command::kMap, "gltf/data-uri.gltf", 0, nullptr},
    // Scenes
    {Command::kRun, "scene/empty.json", 3, "FILE:1:1: error: expected a value, found end of file"},
    {Command::kRun, "scene/truncated.json", 3, "FILE:6:27: error: expected ':', found end of file"},
    {Command::kRun, "scene/binary-garbage.json", 3, "FILE:1:1: error: expected a value, found 'h'"},
    {Command::kRun, "scene/utf16-le-bom.json", 3,
     "FILE:1:1: error: expected UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kRun, "scene/utf16-be-bom.json", 3,
     "FILE:1:1: error: expected UTF-8 text, found a UTF-16 byte-order mark"},
    {Command::kRun, "scene/duplicate-key.json", 3, "FILE:6:7: error: duplicate key \"name\""},
    {Command::kRun, "scene/wrong-type.json", 3,
     "FILE: /meshes/0/mappings/0/projector: expected a string, found an array"},
    {Command::kRun, "scene/unknown-key.json", 3,
     "FILE: /meshes/0/colour: unknown key \"colour\"; expected one of: mappings, model, name, path"},
    {Command::kRun, "scene/undefined-mesh.json", 3,
     "FILE: /outputs/1/mesh: no mesh named \"teapot\"; the scene has: tetrahedron"},
    {Command::kRun, "scene/mesh-path-directory.json", 3,
     "FILE: /meshes/0/path: \"DIR/meshes\" is a folder, not a file"},
    {Command::kRun, "scene/number-1e999.json", 3,
     "FILE:6:17: error: expected a number within the range of a double, found '1e999'"},
    {Command::kRun, "scene/crlf.json", 0, nullptr},
    // Image textures
    {Command::kRenderTexture, "image/empty.png", 3, "FILE: error: cannot read: Not a PNG file"},
    {Command::kRenderTexture, "image/truncated.png", 3,
     "FILE: error: cannot read: truncated PNG (chunk 1, IDAT, is cut off)"},
    {Command::kRenderTexture, "image/corrupt-body.png", 3,
     "FILE: error: cannot read: corrupted PNG (chunk 1, IDAT, fails its CRC)"},
    {Command::kRenderTexture, "image/binary-garbage.png", 3, "FILE: error: cannot read: Not a PNG file"},
    {Command::kRenderTexture, "image/text.png", 3, "FILE: error: cannot read: Not a PNG file"},
    {Command::kRenderTexture, "image/directory.png", 3, "FILE: error: cannot open: Is a directory", Source::kDirectory},
    // OpenEXR headers, walked before OpenEXR allocates by their numbers.
    {Command::kRenderTexture, "image/huge-attribute.exr", 3,
     "FILE: error: cannot read: corrupted OpenEXR (header 0's attribute compression declares 1684930579 bytes, 362 "
     "are left in the file)"},
    {Command::kRenderTexture, "image/wide-data-window.exr", 3,
     "FILE: error: image is 196609 x 4, larger than the 16384 x 16384 limit"},
    // Headers only: the reader must refuse or fail from the header, never allocate its way into a crash.
    {Command::kRenderTexture, "image/16384x16384-rgb.ppm", 3,
     "FILE: error: image is 16384 x 16384, 268435456 pixels, more than the limit of 134217728", Source::kText,
     "P6\n16384 16384\n255\n"},
    {Command::kRenderTexture, "image/16384x8192-gray.pgm", 3,
     "FILE: error: cannot read: the pixels are missing or corrupt", Source::kText, "P5\n16384 8192\n255\n"},
};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The files and folders in `folder`, hidden ones included.
std::set<std::string> listing(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// The file the command would write into the output folder.
std::string outputName(Command command) {
  return command == Command::kMap || command == Command::kRun ? "out.obj" : "out.png";
}

// The command line for `e` reading `file` and writing into the folder `out`.
std::string commandLine(const Entry& e, const std::string& file, const fs::path& out) {
  const std::string output = (out / outputName(e.command)).string();
  switch (e.command) {
    case Command::kMap:
      return "map " + file + " --projector sphere -o " + output;
    case Command::kRun:
      return "run " + file + " --output-dir " + out.string();
    case Command::kRenderTexture:
      return "render " + kCube + " --projector sphere --size 16x16 --texture " + file + " -o " + output;
    case Command::kRenderMesh:
      return "render " + file + " --projector sphere --size 16x16 -o " + output;
  }
  return "";
}

// One test per reader rather than per entry: each test program start costs as much as the uvtk it runs.
class BadInput : public CliTest {
 protected:
  // Checks every entry under `folder` of the catalogue but the unreadable files, which have a test of their own;
  // returns how many it checked.
  int checkFolder(const std::string& folder) {
    int count = 0;
    for (const Entry& e : kEntries)
      if (std::string(e.file).rfind(folder, 0) == 0 && e.source != Source::kUnreadable) check(e), ++count;
    return count;
  }

  // Runs the entry's command with an output folder holding only an earlier output file, and checks the status,
  // the whole of stderr, and that the folder and the earlier file are as they were (a valid input replaces it).
  void check(const Entry& e) {
    const std::string work = std::to_string(++checked_);  // a folder of its own for each entry
    const fs::path out = dir_ / work / "out";
    fs::create_directories(out);
    const std::string file = input(e, work);
    const std::string output = writeText(work + "/out/" + outputName(e.command), kSentinel);
    // A day back, so that rewriting the file, even with the same bytes, shows.
    const fs::file_time_type earlier = fs::last_write_time(output) - std::chrono::hours(24);
    fs::last_write_time(output, earlier);

    const std::string arguments = commandLine(e, file, out);
    SCOPED_TRACE("uvtk " + arguments);
    const CliRun r = uvtk(arguments);
    EXPECT_EQ(r.status, e.status) << r.err;
    // Nothing new in the folder, not even a hidden temporary file.
    EXPECT_EQ(listing(out), std::set<std::string>{outputName(e.command)});
    const std::string folder = fs::path(file).parent_path().string();
    const std::string message = e.message ? replaceAll(replaceAll(e.message, "FILE", file), "DIR", folder) : "";
    if (e.status != 0) {
      EXPECT_EQ(r.err, message + "\n");
      EXPECT_EQ(readText(output), kSentinel);
      EXPECT_EQ(fs::last_write_time(output), earlier);
    } else {
      EXPECT_NE(readText(output), kSentinel) << "a valid input replaces the output";
      // The summary line has timings: only the warning is compared, as a whole line.
      if (e.message) {
        EXPECT_NE(("\n" + r.err).find("\n" + message + "\n"), std::string::npos) << r.err;
      } else {
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
      }
    }
    if (e.source != Source::kCatalogue) fs::remove_all(file);  // the 200 MB line goes at once
  }

 private:
  // The input's path: the catalogue's file, or one generated in the folder `work` of the scratch folder.
  std::string input(const Entry& e, const std::string& work) const {
    if (e.source == Source::kCatalogue) return kCatalogueDir + "/" + e.file;
    const std::string name = work + "/" + fs::path(e.file).filename().string();
    switch (e.source) {
      case Source::kText:
        writeText(name, e.text);
        break;
      case Source::kLongLine: {
        std::ofstream out(path(name), std::ios::binary);
        out << "v 0 0 0 ";
        const std::string spaces(std::size_t{1} << 20, ' ');
        for (int megabytes = 0; megabytes < 200; ++megabytes) out << spaces;
        break;
      }
      case Source::kDirectory:
        fs::create_directory(path(name));
        break;
      case Source::kUnreadable:
        fs::permissions(writeText(name, "v 0 0 0\n"), fs::perms::none);
        break;
      case Source::kCatalogue:
        break;
    }
    return path(name);
  }

  int checked_ = 0;
};

TEST_F(BadInput, ObjMeshes) { EXPECT_EQ(checkFolder("obj/"), 22); }

TEST_F(BadInput, OffMeshes) { EXPECT_EQ(checkFolder("off/"), 24); }

TEST_F(BadInput, PlyMeshes) { EXPECT_EQ(checkFolder("ply/"), 13); }

TEST_F(BadInput, StlMeshes) { EXPECT_EQ(checkFolder("stl/"), 8); }

TEST_F(BadInput, GltfMeshes) { EXPECT_EQ(checkFolder("gltf/"), 15); }

TEST_F(BadInput, Scenes) { EXPECT_EQ(checkFolder("scene/"), 12); }

TEST_F(BadInput, ImageTextures) { EXPECT_EQ(checkFolder("image/"), 10); }

TEST_F(BadInput, UnreadableMeshes) {
  withoutPrivileges(dir_, [&] {  // root reads a file whatever its permissions
    int count = 0;
    for (const Entry& e : kEntries)
      if (e.source == Source::kUnreadable) check(e), ++count;
    EXPECT_EQ(count, 2);
  });
}

// The catalogue, the table above and the tables of docs/robustness.md cannot drift apart: every committed file
// is an entry, and every entry's file and exact message are on that page.
TEST(BadInputCatalogue, EveryFileIsAnEntryAndEveryEntryIsDocumented) {
  std::set<std::string> committed, entries;
  for (const auto& entry : fs::recursive_directory_iterator(kCatalogueDir)) {
    const std::string relative = entry.path().lexically_relative(kCatalogueDir).string();
    // README.md describes the catalogue; scene/meshes/ holds the valid mesh the scenes refer to.
    if (entry.is_regular_file() && relative != "README.md" && relative.rfind("scene/meshes/", 0) != 0)
      committed.insert(relative);
  }
  for (const Entry& e : kEntries)
    if (e.source == Source::kCatalogue) entries.insert(e.file);
  EXPECT_EQ(committed, entries);

  std::ifstream in(std::string(UVTK_SOURCE_DIR) + "/docs/robustness.md");
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(page.empty());
  for (const Entry& e : kEntries) {
    EXPECT_NE(page.find(std::string("`") + e.file + "`"), std::string::npos) << e.file;
    if (e.message) {
      EXPECT_NE(page.find(std::string("`") + e.message + "`"), std::string::npos) << e.message;
    }
  }
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk
