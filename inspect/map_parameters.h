// `uvtk map`'s parameters beyond its projector (the verdict's thresholds, the overlap raster, the
// texture size, the texel density, the threads), read from the same typed dictionary by every
// face: the command line, the library's MapOptions and Python's keywords.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/judgement.h"
#include "param/make_projector.h"

namespace uvtk::inspect {

struct MapSettings {
  param::ProjectorRequest projector;
  analysis::Thresholds thresholds;        // fail-on, warn-on (RULE=VALUE; "warn" and "fail" are the command's)
  int overlapResolution = analysis::kOverlapFollowsMesh;  // or 1 to kMaxOverlapResolution pixels
  analysis::TextureSize textureSize;      // W,H (or N: N,N) texels, 1 to 16384 each
  std::optional<double> density;          // positive and finite
  int threads = 0;                        // 0 to 1024; 0: one per hardware thread
};

// The verdict's thresholds: "fail-on" and "warn-on", RULE=VALUE each ("warn" and "fail" among
// fail-on's are the command's exit, not thresholds: skipped here).
analysis::Thresholds readThresholds(const param::ParameterDictionary& parameters);

// "overlap-resolution": 0 (the raster follows the mesh) to analysis::kMaxOverlapResolution;
// `fallback` when not given. Read by map, report and compare alike.
int readOverlapResolution(const param::ParameterDictionary& parameters, int fallback);
// The same range for a value set in C++ (ReportOptions, CompareOptions): UsageError outside it.
void checkOverlapResolution(int overlapResolution);

// Throws UsageError (ParameterTypeError for a value of the wrong kind) naming the parameter.
MapSettings readMapSettings(const param::ParameterDictionary& parameters);

// Every name readMapSettings reads, for ParameterDictionary::checkAllRead.
std::vector<std::string> mapParameterNames();

}  // namespace uvtk::inspect
