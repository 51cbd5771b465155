// A mesh with its per-corner UVs, from the file's own vt or from a projector, and what analysis
// and the views need to know about where they came from: the step every inspecting subcommand
// (render, report, compare) shares.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "analysis/distortion.h"
#include "analysis/judgement.h"
#include "analysis/texel_layout.h"
#include "core/mesh.h"
#include "core/uv_map.h"
#include "param/projector.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "texgen/texgen.h"
#include "views/views.h"

namespace uvtk::inspect {

struct MappedMesh {
  Mesh mesh;                                         // with a projector and --seam cut, the cut mesh
  UvMap uv;                                          // (s, t) per corner, and r in uv.w where the source has it
  std::vector<double> q;                             // texgen's q per corner; empty means 1
  // The camera projector's q = w_c per corner (1 where invalid), while uv holds the divided
  // (u, v) = (s/q, t/q) the OBJ writes: the renderer interpolates (u q, v q, q) unless baked.
  std::vector<double> cameraQ;
  std::string source;                                // "file", "projector" or "texgen"
  std::optional<param::ProjectorOptions> projector;  // set when a projector made the UVs
  std::optional<param::Projection> projection;       // its summary and frame (its mesh and uv moved out)
  std::optional<param::SeamPlacement> seamPlacement;
  std::optional<render::PixelMapping> exact;  // the mapping evaluated at every pixel (§9); none for a file
  double uvScale = 1.0;  // what scaleToTexelDensity multiplied the UVs by (exact still evaluates the unscaled mapping)

  // (s, t, r, q) per corner, as the renderer takes them; `baked`: the camera projector's divided
  // (u, v) with q = 1, as a baked OBJ gives them (perspective-correct, but not projective).
  std::vector<Vec4> corners(bool baked = false) const;
  // r holds cube face ids (writesCubeFaceIds), not a direction's third component.
  bool cubeFaceIds() const;
  // What the renderer interpolates (per-vertex, `baked` as corners() says) or evaluates at every
  // pixel (per-pixel).
  render::TexcoordSource texcoordSource(bool perPixel, bool baked = false) const;
  // Where a planar projector looks: mapByProjector marks the faces turned away (kFaceTurnedAway), so
  // that they count as backfacing, not flipped.
  analysis::ProjectionDirections projectionDirections() const;
  // The judgement of these UVs (analysis/judgement.h): per-face measures, counts, the summary
  // with the projector's own pole vertices (for other sources the fanned poles found in the UVs),
  // and the verdict under `thresholds`; texel densities counted in `textureSize` texels.
  analysis::Judgement judge(const analysis::Thresholds& thresholds = {}, int overlapResolution = analysis::kOverlapFollowsMesh,
                            int threads = 0, analysis::TextureSize textureSize = {}) const;
  // How far apart the atlas's charts lie in its texture (analysis::measureGutters); nothing
  // unless an atlas (or LSCM, ARAP) made the UVs.
  std::optional<analysis::Gutters> atlasGutters() const;
  // What the views draw: this mesh and its UVs with their judgement (null for views without
  // measures; it must outlive the result).
  views::ViewInput viewInput(const analysis::Judgement* judgement) const;
};

// Whether the projector's r is the cube face id and (s, t) the point on that face: the cube's faces
// layout (render::TexcoordSource::cubeFaceIds); `uvtk map --write-w` writes it as w.
bool writesCubeFaceIds(const param::ProjectorOptions& options);

// Where UVs made by a projector came from, added to a JSON record: "options" and, after
// --seam-place auto, "seam_placement". Nothing for the file's UVs or texgen.
void addMappingOrigin(nlohmann::json& record, const MappedMesh& mapped);

// The summary `uvtk map --json` writes (without the times): the projector's mapping summary (for
// other sources only "texcoords"), the "input" record, the output file, and under "judgement"
// the mapping's judgement (measures_json.h) with its "verdict" and "reasons" also at the top.
nlohmann::json mapSummaryJson(const MappedMesh& mapped, const analysis::Judgement& judgement,
                              const nlohmann::json& input, const std::string& output);

// The camera of the inspection views: it frames the mesh's bounding sphere from the direction
// `viewDir` with `up` (options/view_camera_cli.h reads them as --view-dir and --up).
struct ViewCamera {
  Vec3 viewDir{1.0, -1.5, 0.8};  // from the mesh to the camera
  Vec3 up{0.0, 0.0, 1.0};        // the picture's up
  // Throws InputError naming `meshFile` (when not empty) for a mesh too large to frame.
  render::Camera frame(const Mesh& mesh, const std::string& meshFile, int width, int height) const;
};

// The file's vt as per-corner UVs (w in uv.w): a corner without vt is invalid (kFaceInvalid on its
// face) and reads (0, 0, 0) as GL's current texture coordinate would.
// Throws UsageError when the mesh has no vt at all, naming `path`.
UvMap fileUvs(const Mesh& mesh, const std::string& path);

// `mesh` mapped by `options` (after --seam-place auto when `seamPlaceAuto`) on `threads` (0: one per core).
MappedMesh mapByProjector(Mesh mesh, param::ProjectorOptions options, bool seamPlaceAuto, int threads = 0);

// `mesh` with OpenGL texgen's (s, t, r, q).
MappedMesh mapByTexgen(Mesh mesh, const texgen::TexgenOptions& options);

// `mesh` with its own UVs.
MappedMesh withFileUvs(Mesh mesh, const std::string& path);

// What an inspecting command prints on stderr beside its outputs: the input's warnings, and where
// --seam-place auto put the seam.
void printMappingNotes(const std::string& inputPath, const MeshWarnings& warnings, const MappedMesh& mapped);

}  // namespace uvtk::inspect
