// LSCM and ARAP through CGAL's Surface_mesh_parameterization. With placement_cgal.cpp, the only
// translation units that include CGAL.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "param/baseline.h"

namespace uvtk::param {

namespace {

// Exact predicates matter: ARAP repairs overlaps by triangulating the UV boundary's convex hull
// with the mesh's own kernel.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = SurfaceMesh::Vertex_index;
namespace smp = CGAL::Surface_mesh_parameterization;

// Twice a triangle's area at most this times its longest edge squared: no area to map.
constexpr double kZeroAreaRelative = 1e-14;

std::string prefix(Baseline baseline) { return std::string("parameterizeDisk (") + toString(baseline) + "): "; }

// Why `topology` is not a disk, e.g. "not manifold, 3 boundary loops".
std::string whyNotADisk(const Topology& topology) {
  std::string why;
  auto add = [&](const std::string& reason) { why += (why.empty() ? "" : ", ") + reason; };
  if (!topology.manifold) add("not manifold");
  if (topology.components != 1) add(std::to_string(topology.components) + " components");
  if (topology.boundaryLoops != 1) add(std::to_string(topology.boundaryLoops) + " boundary loops");
  if (topology.eulerCharacteristic != 1) add("Euler characteristic " + std::to_string(topology.eulerCharacteristic));
  return why;
}

// CGAL 5.5's get_error_message() has no entry for ERROR_NO_TOPOLOGICAL_BALL and so names every
// later code wrongly.
const char* describe(smp::Error_code code) {
  switch (code) {
    case smp::OK: return "success";
    case smp::ERROR_EMPTY_MESH: return "empty mesh";
    case smp::ERROR_NON_TRIANGULAR_MESH: return "a face is not a triangle";
    case smp::ERROR_NO_TOPOLOGICAL_DISC: return "not a topological disk";
    case smp::ERROR_NO_TOPOLOGICAL_BALL: return "not a topological ball";
    case smp::ERROR_BORDER_TOO_SHORT: return "the border is too short";
    // The one way ARAP returns it: its map overlaps itself, and the repair (Karni et al. 2005's
    // convex virtual boundary) needs a UV boundary that does not cross itself.
    case smp::ERROR_NON_CONVEX_BORDER: return "the UV map overlaps itself along its boundary, which CGAL cannot repair";
    case smp::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "cannot solve the linear system";
    case smp::ERROR_NO_1_TO_1_MAPPING: return "the UV map is not one-to-one";
    case smp::ERROR_WRONG_PARAMETER: return "wrong parameter";
  }
  return "unknown error";
}

// The positions moved and scaled so that the triangles' bounding box is centred on the origin
// with its longest side 1. LSCM does not mind the scale, but ARAP does: CGAL adds
// lambda (a^2 + b^2 - 1)^2 per triangle, which does not grow with the mesh, to a term that grows
// with its squared size. In the unit box ARAP's result does not depend on the mesh's units.
std::vector<Vec3> inUnitBox(const Mesh& mesh) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) {
      lo = lo.cwiseMin(mesh.positions[v]);
      hi = hi.cwiseMax(mesh.positions[v]);
    }
  const Vec3 centre = (lo + hi) / 2;
  const double side = (hi - lo).maxCoeff();
  std::vector<Vec3> out;
  out.reserve(mesh.vertexCount());
  for (const Vec3& p : mesh.positions) out.push_back((p - centre) / side);
  return out;
}

// Refuses zero-area triangles: they have no conformal or rigid frame of their own (ARAP's
// cotangent weights divide by their area), and CGAL answers them with NaN UVs or worse.
void requireArea(const std::vector<Vec3>& positions, const Mesh& mesh, Baseline baseline) {
  std::size_t degenerate = 0, first = 0;
  for (std::size_t f = 0; f < mesh.faceCount(); ++f) {
    const Vec3& a = positions[mesh.triangles[f][0]];
    const Vec3& b = positions[mesh.triangles[f][1]];
    const Vec3& c = positions[mesh.triangles[f][2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    if (triangleAreaNormal(a, b, c).norm() > kZeroAreaRelative * longest) continue;  // false for NaN too
    if (degenerate++ == 0) first = f;
  }
  if (degenerate > 0)
    throw UsageError(prefix(baseline) + std::to_string(degenerate) +
                     " triangles have zero area (the first is triangle " + std::to_string(first) + ")");
}

// Vertex i and face f of the result are vertex i and triangle f of the mesh.
SurfaceMesh toSurfaceMesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                          Baseline baseline) {
  SurfaceMesh out;
  for (const Vec3& p : positions) out.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const Triangle& t = triangles[f];
    if (out.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])) == SurfaceMesh::null_face())
      throw UsageError(prefix(baseline) + "CGAL's halfedge mesh refused triangle " + std::to_string(f));
  }
  return out;
}

// A halfedge on the boundary: of a disk, on its one boundary loop, where CGAL starts.
SurfaceMesh::Halfedge_index borderHalfedge(const SurfaceMesh& mesh) {
  for (SurfaceMesh::Halfedge_index h : mesh.halfedges())
    if (mesh.is_border(h)) return h;
  checkFailed("a disk has a border halfedge", __FILE__, __LINE__);
}

}  // namespace

UvMap parameterizeDisk(const Mesh& mesh, Baseline baseline) {
  const Topology topology = analyzeTopology(mesh);
  if (!topology.isDisk())
    throw UsageError(prefix(baseline) + "the mesh is not a topological disk (" + whyNotADisk(topology) +
                     "; a disk is manifold, connected, with one boundary loop and Euler characteristic 1)");
  const std::vector<Vec3> positions = inUnitBox(mesh);
  requireArea(positions, mesh, baseline);

  SurfaceMesh surface = toSurfaceMesh(positions, mesh.triangles, baseline);
  const SurfaceMesh::Halfedge_index border = borderHalfedge(surface);
  auto uvs = surface.add_property_map<VertexIndex, Kernel::Point_2>("v:uv").first;
  smp::Error_code status = smp::OK;
  try {
    if (baseline == Baseline::Lscm) {
      // Lévy et al. 2002. The default border parameterizer (Two_vertices_parameterizer_3) pins
      // the two extreme vertices along the bounding box's longest axis.
      status = smp::parameterize(surface, smp::LSCM_parameterizer_3<SurfaceMesh>(), border, uvs);
    } else {
      // Liu et al. 2008, with CGAL's defaults: lambda = 1000 weighs a^2 + b^2 = 1 (a rotation
      // per triangle) heavily enough to be ARAP rather than ASAP (lambda = 0, a conformal map
      // like LSCM's); at most 50 iterations, fewer once the energy changes by less than 1e-6.
      status = smp::parameterize(surface, smp::ARAP_parameterizer_3<SurfaceMesh>(), border, uvs);
    }
  } catch (const CGAL::Failure_exception& e) {  // a CGAL precondition, when assertions are compiled in
    throw UsageError(prefix(baseline) + "CGAL failed: " + e.what());
  }
  if (status != smp::OK) throw UsageError(prefix(baseline) + "CGAL failed: " + describe(status));

  UvMap out;
  out.uv.resize(3 * mesh.faceCount());
  out.faceFlags.assign(mesh.faceCount(), kFaceOk);
  out.cornerInvalid.assign(3 * mesh.faceCount(), 0);
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (std::size_t c = 0; c < out.uv.size(); ++c) {
    const Kernel::Point_2& p = uvs[VertexIndex(mesh.triangles[c / 3][c % 3])];
    out.uv[c] = Vec2(p.x(), p.y());
    if (!out.uv[c].allFinite()) throw UsageError(prefix(baseline) + "CGAL returned a non-finite UV");
    lo = lo.cwiseMin(out.uv[c]);
    hi = hi.cwiseMax(out.uv[c]);
  }
  // One scale for both axes keeps the angles LSCM preserves and the shapes ARAP preserves.
  const double side = (hi - lo).maxCoeff();
  for (Vec2& uv : out.uv) uv = (uv - lo) / side;
  return out;
}

}  // namespace uvtk::param
