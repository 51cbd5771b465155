// Looking at a mapping: its report (every measure and the verdict), pictures of it (the
// inspection views, or the mesh rendered with a texture as OpenGL would), and the ranking of every
// projector on one mesh. Part of <uvtk/uvtk.h> (docs/library.md, docs/views.md).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "uvtk/export.h"
#include "uvtk/mapping.h"

namespace uvtk::api {

// The options of `uvtk report`.
struct ReportOptions {
  std::string json;  // --json: also write the report as JSON here ("" none)
  std::string html;  // --html: also write the self-contained page with the views here ("" none)
  std::string views = "checker,uvgrid,stretch,linf,angle,area,seams,layout,bleed";  // --views: the page's views
  std::string size = "384x384";  // --size: each view's pixels, WxH
  Vector3 viewDir{1, -1.5, 0.8};  // --view-dir: the direction from the mesh to the views' camera
  Vector3 up{0, 0, 1};            // --up: the views' camera's up
  int textureSize = 1024;        // --texture-size: texels N (N x N) of the texture texel density and uverror count in
  int overlapResolution = 0;  // --overlap-resolution: the mapping is judged again when it differs from map()'s
  int threads = 0;               // --threads: 0, one per hardware thread

  // From `uvtk report`'s syntax, e.g. "--views checker,seams --size 256x256".
  UVTK_API static ReportOptions parse(const std::string& commandLine);
  UVTK_API std::string commandLine() const;  // the options that differ from the defaults
  // The options that differ from the defaults, as typed parameters (no text).
  UVTK_API Parameters parameters() const;
  // Every field's option as the command's --help shows it (Python's signatures).
  UVTK_API static std::vector<OptionDescription> describe();
};

// The report of `mapping` as JSON text: the document `uvtk report --json` writes (verdict first,
// every measure, seams, poles, overlap), and the files `options` names, published together.
UVTK_API std::string report(const Mapping& mapping, const ReportOptions& options = {});
// The same from typed parameters (Python's keywords): the names of ReportOptions' options.
UVTK_API std::string report(const Mapping& mapping, const Parameters& parameters);

// An image in memory: values in [0, 1], row 0 at the top.
struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // (y * width + x) * channels + c

  // The 8-bit values a PNG of this image holds: round(clamp(value, 0, 1) * 255), NaN as 0.
  UVTK_API std::vector<std::uint8_t> bytes() const;
};

// The options of `uvtk render` (its defaults: the camera frames the mesh from report's direction).
struct RenderOptions {
  std::string view;  // --view: checker, uvgrid, stretch, linf, angle, area, seams, uverror, layout, mipline, ...;
                     // several, comma-separated: a contact sheet; "" (the default): the textured picture
  std::string size = "512x512";   // --size: WxH
  Vector3 viewDir{1, -1.5, 0.8};  // --view-dir: the direction from the mesh to the camera, which frames the mesh
  std::optional<Vector3> up;      // --up: the camera's up; unset: 0,0,1 along viewDir (0,1,0 looking along z), 0,1,0 with eye
  std::string camera;             // --camera: auto (frames the mesh), explicit (eye, center, up); "": explicit when eye is set
  std::optional<Vector3> eye;     // --eye: gluLookAt eye; unset: the camera frames the mesh along viewDir
  Vector3 center{0, 0, 0};        // --center: gluLookAt centre
  double fovy = 45.0;             // --fovy: gluPerspective field of view in y, degrees
  double zNear = 0.1, zFar = 100.0;  // --near, --far: an explicit camera's clipping planes
  std::string ortho;              // --ortho: glOrtho l,r,b,t, or auto to frame the mesh; "": perspective
  std::string cull = "back";      // --cull: back, front, none
  std::string texture = "checker:64:8";  // --texture (view ""): checker:N[:C], uvgrid[:N], an image file, a cube map
  std::string filter = "nearest";        // --filter: GL's minification filter (view "")
  std::string wrap;               // --wrap: repeat, clamp_to_edge, mirrored_repeat; "": repeat, a cube map's clamp_to_edge
  bool seamless = false;          // --seamless: a cube map filtered across its face edges
  std::string env = "replace";    // --env: replace, modulate, decal, blend (the last three lit by a head-light)
  std::array<double, 4> envColor{0, 0, 0, 0};  // --env-color: GL_TEXTURE_ENV_COLOR, read by blend
  bool twoSided = false;          // --two-sided: back faces lit too (GL_LIGHT_MODEL_TWO_SIDE)
  std::string textureSize = "1024,1024";  // --texture-size: W,H (or N) texels the density view counts in
  int checks = 16;                // --checks: checks across the unit square in the checker view
  std::string layoutFill = "stretch";  // --layout-fill: stretch, linf, angle, area
  int layoutSize = 512;           // --layout-size: pixels across the layout view's UV square
  int spp = 1;                    // --spp: samples per pixel (1, 4, 9, ...), box-filtered
  Vector3 background{0, 0, 0};    // --background: r, g, b in [0, 1]
  std::string uv = "per-vertex";  // --uv: per-vertex (interpolated), per-pixel (the mapping evaluated exactly)
  std::string derivatives = "analytic";  // --derivatives: analytic, quad-coarse, quad-fine (a GPU's 2x2 quad differences)
  std::string seamFix = "none";          // --seam-fix: none, grad, tarini (with quad derivatives)
  int threads = 0;                // --threads: 0, one per hardware thread; the image does not depend on it

  // From `uvtk render`'s syntax, e.g. "--view seams --size 640x480".
  UVTK_API static RenderOptions parse(const std::string& commandLine);
  UVTK_API std::string commandLine() const;  // the options that differ from the defaults
  UVTK_API Parameters parameters() const;    // the same, as typed parameters
  // Every field's option as the command's --help shows it (Python's signatures).
  UVTK_API static std::vector<OptionDescription> describe();
};

// A picture of `mapping`: the image `uvtk render` writes with these options and the mapping's
// (before it is stored as 8 bits: bytes() gives the PNG's values). Views with measures show the
// mapping's judgement.
UVTK_API Image render(const Mapping& mapping, const RenderOptions& options = {});
// The same from typed parameters named as the options (Python's keywords): "view", "size" (WxH as
// text, or W, H), "eye", "ortho" (L, R, B, T or "auto"), ...; an unknown name is a UsageError with
// the nearest.
UVTK_API Image render(const Mapping& mapping, const Parameters& parameters);

// The options of `uvtk compare`.
struct CompareOptions {
  std::string by = "stretch_l2";  // --by: stretch_l2, stretch_linf, angle, seam_length (among mappings with the same verdict)
  int top = 8;                    // --top: mappings in the contact sheet
  bool baselines = true;          // false: --no-baselines (CGAL's LSCM and ARAP)
  int tileSize = 256;             // --tile-size: pixels across each picture of the contact sheet
  Vector3 viewDir{1, -1.5, 0.8};  // --view-dir: the sheet's camera
  Vector3 up{0, 0, 1};            // --up
  int overlapResolution = 0;   // --overlap-resolution: pixels across the overlap raster (as map)
  bool seamPlaceAuto = false;     // --seam-place-auto: every wrapping projector with its seam placed
  int baselineMaxFaces = 200000;  // --baseline-max-faces: LSCM and ARAP only up to this many faces
  std::vector<std::string> failOn, warnOn;  // --fail-on, --warn-on: the verdict's thresholds
  std::string json, markdown, sheet;        // --json, --markdown, --sheet: files to write ("" none)
  int threads = 0;                // --threads: 0, one per hardware thread

  // From `uvtk compare`'s syntax, e.g. "--by angle --no-baselines".
  UVTK_API static CompareOptions parse(const std::string& commandLine);
  UVTK_API std::string commandLine() const;  // the options that differ from the defaults
  // The options that differ from the defaults, as typed parameters (no text).
  UVTK_API Parameters parameters() const;
  // Every field's option as the command's --help shows it (Python's signatures).
  UVTK_API static std::vector<OptionDescription> describe();
};

struct Comparison {
  std::string json;   // the document `uvtk compare --json` writes
  std::string table;  // the Markdown table
  std::string best;   // the first-ranked mapping's name
};

// Every projector configuration on `mesh`, ranked (verdict first): `uvtk compare`.
UVTK_API Comparison compare(const Mesh& mesh, const CompareOptions& options = {});
// The same from typed parameters (Python's keywords): the names of CompareOptions' options.
UVTK_API Comparison compare(const Mesh& mesh, const Parameters& parameters);

}  // namespace uvtk::api
