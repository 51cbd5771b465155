// Texture coordinates for a mesh: by a projector (Bier & Sloan's two stages), by OpenGL's texgen,
// or the file's own; each judged (a verdict with its reasons) exactly as `uvtk map` judges it.
// Options are structs with the command line's names and defaults; parse() reads the command
// line's own syntax. Part of <uvtk/uvtk.h> (docs/library.md; conventions: docs/conventions.md).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "uvtk/export.h"
#include "uvtk/mesh.h"
#include "uvtk/point.h"

namespace uvtk::api {

// One parameter of a mapping as a face gives it: its name as `uvtk map` spells the option without
// the dashes ("cap-angle"), its typed value, and where it came from for messages ("": the face's
// spelling of the name, capAngle for the library, cap_angle for a Python keyword). Nothing
// (std::monostate) is Python's None: "not given" where a parameter is optional, else a
// ParameterTypeError. A choice is its name ("cylinder").
// The point API's (uvtk/point.h): one kind of typed parameter for both libraries.
using ParameterValue = point::ParameterValue;
using Parameter = point::Parameter;
struct Parameters {
  // Who gave them, which decides how a message names a parameter: capAngle (the library's
  // fields), cap_angle (a Python keyword), --cap-angle (a command line, as MapOptions::parse reads it).
  enum class Face { Library, Keyword, CommandLine } face = Face::Library;
  std::vector<Parameter> values;
};

// One option as the command line's --help shows it: what Python's signatures and stubs are made of.
struct OptionDescription {
  std::string name;                  // as the command line spells it without the dashes: "cap-angle"
  std::string kind;                  // bool, int, float, str, float[N] (N numbers), str[] (repeatable),
                                     // float|auto (--seam-place), int|int[2] (--texture-size)
  bool optional = false;             // may be left unset (Python's None: not given)
  std::string defaultText;           // the default as --help shows it ("45", "0,0,1"); "" none
  std::vector<std::string> choices;  // a choice's names, in --help's order; empty for other options
  std::string help;                  // the one-line meaning --help shows
  std::string typeName;              // --help's placeholder of the value: "FLOAT", "X,Y,Z", "WxH", "a|b|c"; "" for a flag
};

// The options of `uvtk map` (docs/conventions.md): each field is the option of that name, with
// its default; a choice is spelled as on the command line.
struct MapOptions {
  std::string projector = "sphere";  // --projector: a surface's name (plane, cylinder, sphere, cube, camera,
                                     // triplanar, atlas, ...: docs/conventions.md §3)
  std::string omap = "isn";          // --omap: isn, centroid, normal, reflection
  std::optional<std::string> fit;    // --fit: none, bbox, center, pca, obb (unset: bbox; triplanar none)
  std::string axis = "z";            // --axis: x, y, z, the object axis that becomes local z (bbox fit)
  std::optional<Vector3> center;     // --center: an explicit placement's origin (replaces the fit)
  Vector3 axisDir{0, 0, 1};          // --axis-dir: the explicit placement's local z
  Vector3 refDir{1, 0, 0};           // --ref-dir: the explicit placement's local x reference
  double scale = 1.0;                // --scale: the explicit placement's object units per local unit
  std::array<double, 4> planeU{1, 0, 0, 0};  // --plane-u: two-plane, the plane whose signed distance is u
  std::array<double, 4> planeV{0, 1, 0, 0};  // --plane-v: two-plane, the plane whose signed distance is v
  bool caps = false;                 // --caps: cylinder, planar caps on faces facing along the axis
  double capAngle = 45.0;            // --cap-angle: degrees between a cap face's normal and the axis
  std::string capLayout = "beside";  // --cap-layout: beside (side band below, caps above), stacked
  std::string spherePreset = "default";  // --sphere-preset: default, glu, seed004
  std::string cubeConvention = "gl";     // --cube-convention: gl, direct
  std::string cubeLayout = "cross";      // --cube-layout: cross, strip, 3x2, faces (face id as w, for cube maps)
  std::optional<Vector3> eye;        // --eye: the reflection O-mapping's eye in object space; camera: gluLookAt eye
  std::optional<Vector3> up;         // --up: camera, gluLookAt up (0, 1, 0 when unset); --center is its centre
  double fovy = 45.0;                // --fovy: camera, gluPerspective field of view in y, degrees
  double aspect = 1.0;               // --aspect: camera, gluPerspective width / height
  double tile = 1.0;                 // --tile: triplanar, UV units per unit of the projector's frame
  double blend = 1.0;                // --blend: triplanar, the weights' exponent (materialx: its blend)
  std::string triplanarPreset = "unity";  // --triplanar-preset: unity, materialx, godot
  double angleLimit = 66.0;          // --angle-limit: atlas, degrees between a face's normal and its chart's direction
  double margin = 4.0;               // --margin: atlas, texels of gutter between charts and from the border
  std::optional<double> texelsPerUnit;  // --texels-per-unit: atlas, every chart's density (unset: the most that fit)
  bool atInfinity = false;           // --at-infinity: reflection, look up by direction only
  std::string seam = "shift";        // --seam: none, shift (u in [0, 1.5)), cut (u in [0, 1])
  std::string pole = "fan";          // --pole: none (u = 0), fan (mean u of the face's other corners)
  double poleEps = 1e-6;             // --pole-eps: a pole is hypot(x, y) <= eps |q|
  std::optional<double> seamPlace;   // --seam-place DEGREES: the seam turned to this azimuth
  bool seamPlaceAuto = false;        // --seam-place auto: where it crosses the fewest faces
  Vector2 uvScale{1, 1};             // --uv-scale: the UV transform's scale
  Vector2 uvOffset{0, 0};            // --uv-offset: its offset
  double uvRotate = 0.0;             // --uv-rotate: its turn in degrees about (0.5, 0.5)
  bool flipU = false, flipV = false;  // --flip-u, --flip-v: u -> 1 - u, v -> 1 - v, first
  std::string precision = "double";  // --precision: double, float
  std::string math = "exact";        // --math: exact, fast, fast-u10
  std::string convention = "uvtk";   // --convention: uvtk, blender, assimp, notes
  std::vector<std::string> failOn;   // --fail-on: RULE=VALUE thresholds of the verdict (docs/conventions.md §11)
  std::vector<std::string> warnOn;   // --warn-on: RULE=VALUE
  int overlapResolution = 0;         // --overlap-resolution: pixels across the overlap raster; 0 follows the mesh (256 to 1024)
  std::array<int, 2> textureSize{1024, 1024};  // --texture-size: texels W, H that texel density counts in
  std::optional<double> density;     // --density: scale the UVs to this mean texel density (unset: leave them)
  int threads = 0;                   // --threads: 0 is one per hardware thread

  // The options from `uvtk map`'s syntax, e.g. "--projector cylinder --fit obb --caps". Throws
  // std::invalid_argument with the command line's message.
  UVTK_API static MapOptions parse(const std::string& commandLine);
  // The options as `uvtk map` takes them (the ones that differ from the defaults).
  UVTK_API std::string commandLine() const;
  // The options that differ from the defaults, as typed parameters (no text).
  UVTK_API Parameters parameters() const;
  // Every field's option as `uvtk map --help` shows it, in the struct's order.
  UVTK_API static std::vector<OptionDescription> describe();
};

// The options of `uvtk texgen`: OpenGL's glTexGen for s, t, r and q under a gluLookAt view.
struct TexgenOptions {
  // --s, --t, --r, --q: "MODE" or "MODE:a,b,c,d", MODE one of object_linear, eye_linear,
  // sphere_map, normal_map, reflection_map, off; "" leaves the coordinate to `mode` or off.
  std::string s, t, r, q;
  std::string mode;                      // --mode: sphere_map, normal_map, reflection_map (s, t, and r)
  std::optional<std::array<double, 16>> texmatrix;  // --texmatrix: column-major; q is kept, not divided
  bool normalize = true;                 // false: --no-normalize (GL's default state)
  Vector3 eye{0, 0, 0};                  // --eye: gluLookAt eye
  Vector3 center{0, 0, -1};              // --center: gluLookAt centre
  Vector3 up{0, 1, 0};                   // --up: gluLookAt up
  std::optional<std::array<double, 16>> model;  // --model: column-major model matrix
  std::string precision = "double";      // --precision: double, float
  int threads = 0;                       // --threads: those the mesh is read, judged and written with (0: one
                                         // per hardware thread)

  // From `uvtk texgen`'s syntax, e.g. "--s object_linear:1,0,0,0 --t eye_linear:0,1,0,0".
  UVTK_API static TexgenOptions parse(const std::string& commandLine);
  UVTK_API std::string commandLine() const;
  // The options that differ from the defaults, as typed parameters (no text).
  UVTK_API Parameters parameters() const;
  // Every field's option as `uvtk texgen --help` shows it.
  UVTK_API static std::vector<OptionDescription> describe();
};

enum class CornerState : std::uint8_t {
  Ok = 0,
  Pole = 1,     // on the axis of a wrapping surface: v is exact, u was repaired (--pole fan) or is 0
  Invalid = 2,  // no texture coordinate: `invalidReason` says why
};

// Why a corner has no texture coordinate (the JSON's names).
enum class InvalidReason : std::uint8_t { Valid = 0, Miss, Behind, OutOfRange, NotFinite, NoTexcoord };

// Per-face flags (bits).
enum FaceFlag : std::uint8_t {
  kFaceInvalid = 1 << 0,            // a corner has no valid texture coordinate
  kFacePole = 1 << 1,               // the face touches the projector's axis
  kFaceSeamStraddle = 1 << 2,       // the corners' u spanned more than 0.5 before seam repair
  kFaceCubeSeam = 1 << 3,           // the corners alone would have chosen different cube faces
  kFaceCap = 1 << 4,                // mapped by a cylinder's planar cap
  kFaceSphereMapSingular = 1 << 5,  // a texgen sphere_map corner at its singular point
  kFaceTurnedAway = 1 << 6,         // turned away from a planar projection: mirrored by design (backfacing)
};

// One reason of a verdict (docs/conventions.md §11).
struct Reason {
  std::string rule;      // e.g. "flipped_area"
  std::string severity;  // "warn" or "fail"
  double value = 0.0, threshold = 0.0;
  std::size_t faces = 0;  // the faces it concerns
  std::string text;       // "flipped_area 0.42 > 0.001 (1,152 faces)"
};

struct Verdict {
  std::string status = "pass";  // "pass", "warn" or "fail"
  std::vector<Reason> reasons;  // the failures first, then the warnings
};

struct MappingDetail;  // what reports and renders need besides the numbers; opaque

// A mesh with texture coordinates per corner, and their judgement.
struct Mapping {
  Mesh mesh;                 // what the coordinates belong to: the input, or cut along the seam (--seam cut)
  std::vector<Vector2> uv;   // (s, t) per corner, corner k of face f at 3 f + k; (0, 0) where invalid
  std::vector<double> w;     // per corner: the cube face id (--cube-layout faces) or texgen's r; empty if none
  std::vector<double> q;     // texgen's q per corner, not divided out; empty means 1
  std::vector<CornerState> state;             // per corner
  std::vector<InvalidReason> invalidReason;   // per corner
  std::vector<std::uint8_t> faceFlags;        // per face: FaceFlag bits
  std::string source;        // "projector", "texgen" or "file"
  Verdict verdict;           // under the options' thresholds
  std::string summaryJson;   // the record `uvtk map --json` writes (without times and output), as JSON text
  std::shared_ptr<const MappingDetail> detail;
};

// `mesh` mapped by a projector, as `uvtk map` maps it (the same numbers, bit for bit).
UVTK_API Mapping map(const Mesh& mesh, const MapOptions& options = {});
// The same from typed parameters (Python's keywords): every name `uvtk map` takes but its outputs;
// a name it does not take is std::invalid_argument with the nearest one.
UVTK_API Mapping map(const Mesh& mesh, const Parameters& parameters);
// A mapping's data made a mapping again (Python's unpickling): `data`'s mesh, uv, w, q, state,
// invalidReason, faceFlags, source, verdict and summaryJson as map(), texgen() or fileUvs() gave
// them (its detail is ignored). Not mapped nor judged again: writeMesh writes it as the mapping
// it came from (the same bytes; not a texgen mapping's, whose options decide its file), report()
// and render() refuse it (std::invalid_argument), for what they read of the engine is not in the
// data. Throws std::invalid_argument when the arrays do not match the mesh.
UVTK_API Mapping restoreMapping(Mapping data);
// `mesh` with OpenGL texgen's (s, t, r, q), as `uvtk texgen` computes them.
UVTK_API Mapping texgen(const Mesh& mesh, const TexgenOptions& options);
// The same from typed parameters (Python's keywords): every name `uvtk texgen` takes but its outputs.
UVTK_API Mapping texgen(const Mesh& mesh, const Parameters& parameters);
// The mesh's own texture coordinates, judged. Throws std::invalid_argument when it has none.
UVTK_API Mapping fileUvs(const Mesh& mesh);

struct WriteOptions {
  std::string uvDigits = "double";  // "double": UV text that round-trips a double; "float": up to 9 digits
  bool writeW = false;              // OBJ: write the third component (the cube face id, texgen's r)
  bool ascii = false;               // PLY: ASCII text instead of binary little endian
  std::string header;               // OBJ and PLY: comment lines at the top ("uvtk map IN" as the program writes)
  int threads = 0;                  // OBJ: threads formatting the text (0: one per hardware thread); same bytes
};

// Writes the mapping's mesh with per-corner texture coordinates, by the path's extension (.obj,
// .ply, .glb, or .gltf with its .bin beside it), as `uvtk map -o` does (a texgen mapping as
// `uvtk texgen -o`: r where generated and the format holds it, and divided by q where q is not 1).
UVTK_API void writeMesh(const std::string& path, const Mapping& mapping, const WriteOptions& options = {});

}  // namespace uvtk::api
