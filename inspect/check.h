// The texture coordinates stored in a mesh file against those a mapping gives (a projector, with
// its conventions, or GL texgen), or against another file's, corner by corner: statistics, the
// worst corners, a JSON record, a heatmap, and a pass/fail status. `uvtk check` (docs/check.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "analysis/judgement.h"
#include "core/math.h"
#include "param/projector.h"
#include "texgen/texgen.h"

namespace uvtk::inspect {

struct CheckOptions {
  std::string input;    // the mesh whose stored UVs are checked (every face with vt unless `partial`)
  std::string against;  // another file's UVs (same vertices and faces); empty: the mapping below
  bool wrapU = false;   // with `against`: u compared modulo 1
  // The mapping, without `against`: one of the two. Never --seam cut: it changes the triangles.
  std::optional<param::ProjectorOptions> projector;
  bool seamPlaceAuto = false;  // the projector's seam placed on the mesh first
  std::optional<texgen::TexgenOptions> texgen;
  bool partial = false;      // faces without vt: their corners are invalid, not an input error
  int textureSize = 1024;    // texels per UV unit, for the errors in texels (positive)
  std::size_t worst = 10;    // how many of the worst corners to list
  std::optional<double> tolerance;  // pass when the main corners' largest error is within it
  analysis::Thresholds thresholds;  // the stored UVs judged as a layout
  std::string json;                 // the record; none when empty
  std::string view;                 // the per-corner error heatmap (8-bit image); none when empty
  int viewWidth = 512, viewHeight = 512;
  Vec3 viewDir{0, 0, 1}, viewUp{0, 1, 0};  // the heatmap's camera
};

struct CheckRun {
  std::string text;  // the report for stdout, every line ending in '\n', the status last
  bool pass = true;  // no tolerance, or the largest main error within it
  analysis::Verdict storedVerdict = analysis::Verdict::Pass;  // of the stored UVs as a layout
};

// Reads the mesh (and `against`), compares, writes the record and the heatmap (published
// together) and returns the report. The input's warnings and the mapping's notes go to stderr.
// Throws InputError for a face without vt (unless `partial`), a file without any vt, and an
// `against` file of another topology.
CheckRun checkStoredUvs(const CheckOptions& options);

}  // namespace uvtk::inspect
