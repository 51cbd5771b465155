// Seam placement: a wrapping projector turned about its axis so that its seam crosses the fewest
// faces. A face straddles the seam (§5) when the seam's azimuth lies strictly inside one of the
// gaps shorter than half a turn between its (non-pole) corners' azimuths, so one sweep over those gaps
// counts the straddling faces of every candidate seam position at once.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/error.h"
#include "param/projector.h"

#include <cstdio>

#include "core/progress.h"
#include "core/seam_edges.h"
#include "param/surfaces.h"

namespace uvtk::param {

namespace {

// The seam edges' total length as the judgement measures it (the one seam rule), with the
// projection's own pole vertices.
double seamLength(const Projection& projection) {
  return classifySeamEdges(projection.mesh, projection.uv).length();
}

struct SeamCandidate {
  double position = 0.0;  // in turns from the current seam, [0, 1)
  std::size_t faces = 0;  // faces the seam crosses there
  double width = 0.0;     // the gap between corner azimuths it sits in, in turns
};

// The seam position that crosses the fewest faces, given per-corner u measured in turns from the
// current seam ([0, 1); NaN for a corner that does not count: a pole or an invalid corner) and
// which faces count. Among equal counts the widest gap wins.
SeamCandidate bestSeamPosition(const std::vector<double>& turns, const std::vector<bool>& counted) {
  std::vector<std::pair<double, int>> events;  // (position, +1 a gap opens / -1 it closes)
  std::size_t openAtZero = 0;
  for (std::size_t f = 0; f < counted.size(); ++f) {
    if (!counted[f]) continue;
    std::array<double, 3> t{};
    int n = 0;
    for (int k = 0; k < 3; ++k)
      if (!std::isnan(turns[3 * f + std::size_t(k)])) t[std::size_t(n++)] = turns[3 * f + std::size_t(k)];
    std::sort(t.begin(), t.begin() + n);
    for (int k = 0; k < n && n > 1; ++k) {  // the gaps between circularly neighbouring corners
      const double start = t[std::size_t(k)];
      const double end = k + 1 < n ? t[std::size_t(k + 1)] : t[0] + 1.0;
      if (!(end - start > 0.0 && end - start < 0.5)) continue;
      events.emplace_back(start, +1);
      if (end < 1.0) {
        events.emplace_back(end, -1);
      } else {  // the gap wraps past the current seam
        ++openAtZero;
        events.emplace_back(end - 1.0, -1);
      }
    }
  }
  if (events.empty()) return {0.5, 0, 1.0};
  std::sort(events.begin(), events.end());

  // Walk the distinct positions; the segment after the last wraps round to the first.
  SeamCandidate best;
  bool found = false;
  long count = static_cast<long>(openAtZero);
  const double first = events.front().first;
  for (std::size_t i = 0; i < events.size();) {
    const double at = events[i].first;
    for (; i < events.size() && events[i].first == at; ++i) count += events[i].second;
    const double next = i < events.size() ? events[i].first : first + 1.0;
    const double width = next - at;
    if (!(width > 0.0)) continue;
    const SeamCandidate candidate{std::fmod(0.5 * (at + next), 1.0), static_cast<std::size_t>(count), width};
    if (!found || candidate.faces < best.faces || (candidate.faces == best.faces && candidate.width > best.width)) {
      best = candidate;
      found = true;
    }
  }
  return best;
}

}  // namespace

SeamPlacement placeSeam(const Mesh& mesh, const ProjectorOptions& options) {
  if (options.surface != SurfaceKind::Cylinder && options.surface != SurfaceKind::Sphere)
    throw UsageError("--seam-place: only the wrapping projectors (cylinder, sphere) have a seam to place");
  const double uStart = uPeriodStartOf(options).value_or(0.0);
  const double uPerTurn = options.surface == SurfaceKind::Sphere ? SphereSurface{options.spherePreset}.uPerTurn()
                                                                 : CylinderSurface{}.uPerTurn();

  // The corners' u as mapped, before any seam or pole repair and UV transform.
  ProjectorOptions raw = options;
  raw.seam = SeamMode::None;
  raw.pole = PoleMode::None;
  raw.uvTransform = UvTransform{};
  const Projection unrepaired = project(mesh, raw);
  // As repairSeams decides (param/seams.h): cap and invalid faces never straddle, pole corners
  // have no u and do not count, faces that wind around the axis straddle wherever the seam is.
  std::vector<bool> counted(unrepaired.uv.faceCount());
  for (std::size_t f = 0; f < counted.size(); ++f)
    counted[f] = (unrepaired.uv.faceFlags[f] & (kFaceInvalid | kFaceCap)) == 0;
  std::vector<bool> pole(mesh.vertexCount(), false);
  for (const int v : unrepaired.summary.poleVertexList) pole[std::size_t(v)] = true;
  std::vector<double> turns(unrepaired.uv.uv.size());
  for (std::size_t c = 0; c < turns.size(); ++c) {
    const double t = unrepaired.uv.uv[c].x() - uStart;
    const bool skip = pole[std::size_t(mesh.triangles[c / 3][c % 3])] || unrepaired.uv.cornerInvalid[c] != 0;
    turns[c] = skip ? std::numeric_limits<double>::quiet_NaN() : t - std::floor(t);
  }
  const SeamCandidate best = bestSeamPosition(turns, counted);

  const Projection before = project(mesh, options);
  SeamPlacement placement;
  placement.turnDegrees = options.placement.turnDegrees;
  placement.facesCrossed = placement.facesCrossedBefore = before.summary.straddlingFaces;
  placement.seamLength = placement.seamLengthBefore = seamLength(before);
  if (best.faces >= before.summary.straddlingFaces) return placement;

  // u measured from the seam grows by uPerTurn per counter-clockwise turn of the azimuth.
  double turn = options.placement.turnDegrees + uPerTurn * 360.0 * best.position;
  turn = std::remainder(turn, 360.0);
  ProjectorOptions turned = options;
  turned.placement.turnDegrees = turn;
  const Projection after = project(mesh, turned);
  placement.turnDegrees = turn;
  placement.facesCrossed = after.summary.straddlingFaces;
  placement.seamLength = seamLength(after);
  return placement;
}

void printSeamPlacement(const SeamPlacement& p) {
  if (quiet()) return;  // a note, not a warning
  char line[256];
  std::snprintf(line, sizeof line,
                "uvtk: seam placed at %.6g degrees: it crosses %zu faces (%zu before), seam length %.6g (%.6g before)",
                p.turnDegrees, p.facesCrossed, p.facesCrossedBefore, p.seamLength, p.seamLengthBefore);
  printProgressMessage(line);  // above a progress bar, not through it
}

}  // namespace uvtk::param
