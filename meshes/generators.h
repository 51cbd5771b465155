// The sample meshes of the toolkit, generated rather than stored so that tests and benchmarks
// can ask for any resolution. Every mesh is closed or a clean open surface, its triangles
// counter-clockwise seen from outside, and its special points exact: poles at (0, 0, +-r), the
// seam meridian at y = +0, quarter turns at exact coordinates.
#pragma once

#include <string>
#include <vector>

#include "core/mesh.h"

namespace uvtk::meshes {

// Sphere of `radius` about the origin with `longitudes` meridians (>= 3) and `latitudes`
// stacks (>= 2). One vertex per pole, north pole first, then the rings from north to south,
// each starting on the +x half-plane (y = 0) and running counter-clockwise seen from +z.
// Vertices: longitudes (latitudes - 1) + 2; faces: 2 longitudes (latitudes - 1).
Mesh latLongSphere(int longitudes, int latitudes, double radius = 1.0);

// Texture coordinates (repeatsS s, repeatsT t, 0, 1) per corner of a mesh around the origin:
// longitude / 2 pi and colatitude / pi of each corner's direction, s made continuous across the
// seam (y = +0) within each triangle and a pole corner given the mean s of its triangle's others.
// What the rendering benchmark and the rasterizer's identity test draw.
std::vector<Vec4> latLongCornerTexcoords(const Mesh& mesh, double repeatsS, double repeatsT);

// Icosahedron subdivided `level` times (each triangle into 4), vertices pushed to `radius`.
// Vertices: 10 * 4^level + 2; faces: 20 * 4^level.
Mesh icosphere(int level, double radius = 1.0);

// Cylinder about the z axis from z = 0 to z = height, `segments` around (>= 3), `stacks` along
// (>= 1). Ring k (bottom first) starts on the +x half-plane. `capped` adds a centre vertex on
// the axis at each end and a fan of `segments` triangles (the bottom cap first, then the top).
Mesh cylinder(int segments, int stacks, double radius, double height, bool capped);

// The box [-1, 1]^3 with each face an n x n grid of quads (two triangles each), vertices welded
// along the box's edges. Vertices: 6 n^2 + 2; faces: 12 n^2.
Mesh cube(int subdivisions);

// Torus about the z axis: tube centre radius `majorRadius`, tube radius `minorRadius`,
// `majorSegments` around the axis and `minorSegments` around the tube (both >= 3).
Mesh torus(int majorSegments, int minorSegments, double majorRadius, double minorRadius);

// Rectangle width x height in the plane z = 0, centred on the origin, facing +z, divided into
// nx x ny quads (two triangles each).
Mesh planeGrid(int nx, int ny, double width, double height);

// ---- Meshes like real ones: what the tests run every feature on ----
// Each is deterministic (a fixed hash, no random state), so a test can assert exact counts.

// A (p, q) torus knot tube: the curve ((R + cos(q t)) cos(p t), (R + cos(q t)) sin(p t), -sin(q t))
// with R = 2, swept by a circle of `tubeRadius` in the curve's Frenet frame. Closed, genus 1,
// knotted: no projector opens it into a disk. `segments` along the curve, `sides` around (>= 3).
Mesh torusKnot(int p, int q, int segments, int sides, double tubeRadius = 0.4);

// A long bone-like solid of revolution about z, from z = 0 to z = length: a thin shaft with knobby
// ends, an elliptical, gently twisted and bumpy cross-section, and one pole vertex at each end
// (first the one at z = 0, last the one at z = length). Closed, genus 0. `stacks` >= 4, `sides` >= 3.
Mesh bone(int stacks, int sides, double length = 10.0);

// An icosphere of `level` with a deterministic scan-like relief (a few smooth lobes and a fine
// hash noise of relative amplitude `noise`), centred off the origin at (0.3, -0.2, 0.1). Closed.
Mesh bumpyBlob(int level, double noise = 0.02);

// An open patch cut from bumpyBlob(level): the faces whose centroid has x above a noisy threshold
// near -0.2, vertices renumbered, unreferenced ones dropped: a curved scan with one ragged
// boundary loop, like the front of a scanned head.
Mesh scannedPatch(int level);

}  // namespace uvtk::meshes

namespace uvtk::meshes {

// A sample mesh shipped in meshes/ (an OBJ, or a PLY or GLB as its extension says): the file's
// name, the call that made it.
struct BundledMesh {
  const char* file;
  const char* recipe;
  Mesh mesh;
  // The comment the file starts with.
  std::string header() const { return std::string("uvtk sample mesh: ") + recipe + " (meshes/generators.h)"; }
};

// The meshes committed under meshes/, written there by `uvtk_meshgen meshes` (a test checks
// that the files are exactly what this list generates).
std::vector<BundledMesh> bundledMeshes();

}  // namespace uvtk::meshes
