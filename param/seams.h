// Seams and poles of the wrapping surfaces (docs/conventions.md §5), on per-corner fields.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/mesh.h"
#include "core/uv_map.h"
#include "param/projector.h"

namespace uvtk::param {

// Per-corner working data of a projection (3 entries per triangle).
struct CornerField {
  std::vector<Vec2> uv;
  std::vector<double> w;  // cube face id, or empty
  std::vector<CornerState> state;
  std::vector<CornerInvalid> reason;  // kCornerValid exactly where state is not Invalid
  std::vector<std::uint8_t> faceFlags;

  // UVs left uninitialised (every corner is written once), their pages faulted in on `threads` threads.
  void resize(std::size_t faceCount, int threads = 1);
  // Corner i has no (u, v), for `why`: written (0, 0), its face flagged kFaceInvalid.
  void invalidate(std::size_t i, CornerInvalid why);
  // Invalid corners become (0, 0) with their reason in cornerInvalid; on `threads` threads.
  UvMap toUvMap(int threads = 1) &&;
};

// Whether the closed triangle (a, b, c) contains the origin: for hit points projected along the
// axis, whether the face touches or encloses the axis. Scaling a corner by a positive factor
// does not change the answer, so hit points need no normalisation.
bool enclosesAxis(const Vec2& a, const Vec2& b, const Vec2& c);

// (u, v) of the mapping at an object-space point and normal; false if invalid or a pole.
using SeamPointEvaluator = std::function<bool(const Vec3& position, const Vec3& normal, Vec2& uv)>;

struct SeamReport {
  std::size_t straddlingFaces = 0;
  std::size_t addedVertices = 0, addedFaces = 0;
};

// Finds faces whose non-pole corners span more than half a turn and, unless mode is None, adds 1
// to their low corners; with Cut, also splits them on the seam (new vertices appended to the mesh,
// each straddling triangle replaced in place by its pieces). u lies in [uStart, uStart + 1).
// The faces are examined on `threads` threads (0: one per core); the cut runs on one.
SeamReport repairSeams(Mesh& mesh, CornerField& corners, double uStart, SeamMode mode,
                       const SeamPointEvaluator& evaluateAt, int threads = 1);

// Gives each pole corner the mean u of its face's other valid corners.
void fanPoleCorners(CornerField& corners, int threads = 1);

// Counts for the summary: poles, invalid vertices, corners per reason, cube seams and caps. The seam
// edges are the one rule's (core/seam_edges.h), on the UVs the projection ends with.
// On `threads` threads, the same counts and lists on any number.
MappingSummary summarize(const Mesh& mesh, const CornerField& corners, const SeamReport& seams, int threads = 1);

}  // namespace uvtk::param
