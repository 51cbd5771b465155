// Stored texture coordinates against the ones a mapping gives, corner by corner: the comparison
// behind `uvtk check` (docs/check.md). Seam shifts do not count (u is compared modulo the period
// on wrapping surfaces), pole corners compare only what is defined there, and corners without a
// value on either side are set apart rather than compared.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/mesh.h"
#include "core/uv_map.h"

namespace uvtk::analysis {

// A corner's error is wrappedUvError (core/uv_map.h).

// Nearest-rank statistics of a list of errors: max, the 99th percentile as the value of rank
// ceil(0.99 n) in ascending order (1-based; no interpolation, so it is always one of the errors),
// and the mean. All zero for no values.
struct ErrorStatistics {
  std::size_t count = 0;
  double max = 0.0, p99 = 0.0, mean = 0.0;
};
ErrorStatistics errorStatistics(std::vector<double> values);

// How a corner takes part in a check.
enum class CornerClass : std::uint8_t {
  Main,      // compared fully; counts in the main statistics and decides the check
  Pole,      // at a pole vertex: only the component across the period compared; pole statistics
  PoleFace,  // another corner of a pole face (kFacePole): compared fully; pole statistics
  Invalid,   // no expected value (the mapping has none there) or no found value: not compared
};

struct CornerError {
  std::size_t corner = 0;  // 3 f + k: corner k of face f
  double error = 0.0;
};

// The `count` largest errors of the corners of class `which` (Pole: Pole and PoleFace together),
// largest first; equal errors in ascending corner order. `error` and `classes` have one entry per corner.
std::vector<CornerError> worstCorners(const std::vector<double>& error, const std::vector<CornerClass>& classes,
                                      CornerClass which, std::size_t count);

struct UvCheckOptions {
  // One turn of u in UV units, T(1, 0) - T(0, 0) for the mapping's UV transform T: (1, 0) on a
  // cylinder or sphere without a transform; zero where nothing wraps (plane, cube, texgen, files).
  // Faces flagged kFaceCap never wrap.
  Vec2 period = Vec2::Zero();
  std::vector<std::uint8_t> poleCorners;  // per corner, 1 at a pole (the reference's UvMap::cornerPole); empty: none
  std::size_t worst = 10;                 // the length of UvCheck::worst and worstPole
};

struct UvCheck {
  std::vector<double> error;                         // per corner, wrappedUvError; NaN for invalid corners
  std::vector<CornerClass> cornerClass;              // per corner
  ErrorStatistics main;                              // over the Main corners
  ErrorStatistics pole;                              // over the Pole and PoleFace corners together
  std::size_t poleCorners = 0, poleFaceCorners = 0;  // corners of class Pole, PoleFace
  std::size_t poleFaces = 0;                         // faces flagged kFacePole
  std::vector<std::size_t> invalidCorners;           // ascending
  std::size_t noExpected = 0, noFound = 0;           // invalid corners by cause (a corner with both counts in both)
  std::vector<CornerError> worst, worstPole;         // worstCorners of Main, and of Pole and PoleFace together
};

// Compares `found` with `expected` corner by corner (both 3 corners per face, same face count).
// `expected` gives the faces' flags (kFacePole, kFaceCap) and, in cornerInvalid, where the mapping
// has no value; found.cornerInvalid (if not empty) marks corners that have no value to check.
// A corner is Invalid when either side has no value; else Pole when options.poleCorners marks it,
// else PoleFace on a kFacePole face, else Main. Pole corners of a non-pole face (a pole vertex on
// a face that does not touch the axis cannot happen for a projector, but the input may say so)
// are Pole all the same.
UvCheck checkUvs(const UvMap& expected, const UvMap& found, const UvCheckOptions& options);


}  // namespace uvtk::analysis
