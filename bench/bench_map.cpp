// Mapping throughput on a 2048 x 1024 lat-long sphere (2.1 M vertices), single-threaded:
// - mapVertices: the two-stage mapping per vertex into a reused buffer (the number to compare
//   with other per-vertex UV generators);
// - project: the whole job of `uvtk map` short of file I/O: placement fit, per-corner UVs,
//   pole and seam repair, summary.
// - atan2: the arctangent alone over the sphere's (y, x), ours (param::arcTangent2) against
//   glibc's std::atan2, the cost that dominates the sphere and cylinder.
// `per_vertex` is seconds per vertex, printed with an SI prefix: "12.3n" is 12.3 ns.
#include <benchmark/benchmark.h>

#include <cmath>

#include "meshes/generators.h"
#include "param/formulas.h"
#include "param/projector.h"

namespace {

using namespace uvtk;
using param::RayKind;
using param::SurfaceKind;

const Mesh& sphere() {
  static const Mesh mesh = meshes::latLongSphere(2048, 1024);
  return mesh;
}

param::ProjectorOptions optionsFor(SurfaceKind surface, RayKind ray) {
  param::ProjectorOptions options;
  options.surface = surface;
  options.ray = ray;
  if (ray == RayKind::Reflection) options.eye = Vec3(0, 0, 5);
  return options;
}

void setPerVertex(benchmark::State& state, std::size_t vertices) {
  state.counters["per_vertex"] = benchmark::Counter(static_cast<double>(vertices),
                                                    benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void mapVertices(benchmark::State& state, SurfaceKind surface, RayKind ray) {
  const Mesh& mesh = sphere();
  const param::ProjectorOptions options = optionsFor(surface, ray);
  const Affine3 localFromObject = param::fitPlacement(mesh.positions, surface, options.placement);
  const std::vector<Vec3> normals = ray == RayKind::SurfaceNormal || ray == RayKind::Centroid
                                        ? std::vector<Vec3>()
                                        : areaWeightedVertexNormals(mesh);
  std::vector<param::VertexUv> out(mesh.vertexCount());  // allocated (and paged in) before timing
  param::mapVertices(options, localFromObject, mesh.positions, normals, out);
  for (auto _ : state) {
    param::mapVertices(options, localFromObject, mesh.positions, normals, out);
    benchmark::DoNotOptimize(out.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

void project(benchmark::State& state, SurfaceKind surface, RayKind ray) {
  const Mesh& mesh = sphere();
  const param::ProjectorOptions options = optionsFor(surface, ray);
  for (auto _ : state) {
    param::Projection p = param::project(mesh, options);
    benchmark::DoNotOptimize(p.uv.uv.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

template <double (*Atan2)(double, double)>
void atan2OverTheSphere(benchmark::State& state) {
  const Mesh& mesh = sphere();
  std::vector<double> angles(mesh.vertexCount());
  for (auto _ : state) {
    for (std::size_t i = 0; i < angles.size(); ++i) angles[i] = Atan2(mesh.positions[i].y(), mesh.positions[i].x());
    benchmark::DoNotOptimize(angles.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

double libmAtan2(double y, double x) { return std::atan2(y, x); }

BENCHMARK_TEMPLATE(atan2OverTheSphere, param::arcTangent2)->Name("atan2/uvtk")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(atan2OverTheSphere, libmAtan2)->Name("atan2/glibc")->Unit(benchmark::kMillisecond);

#define UVTK_MAP_BENCHMARKS(name, surface, ray)                                                      \
  BENCHMARK_CAPTURE(mapVertices, name, surface, ray)->Unit(benchmark::kMillisecond)->MinTime(1.0); \
  BENCHMARK_CAPTURE(project, name, surface, ray)->Unit(benchmark::kMillisecond)->MinTime(1.0)

UVTK_MAP_BENCHMARKS(plane_isn, SurfaceKind::Plane, RayKind::SurfaceNormal);
UVTK_MAP_BENCHMARKS(two_plane_isn, SurfaceKind::TwoPlane, RayKind::SurfaceNormal);
UVTK_MAP_BENCHMARKS(cylinder_isn, SurfaceKind::Cylinder, RayKind::SurfaceNormal);
UVTK_MAP_BENCHMARKS(sphere_isn, SurfaceKind::Sphere, RayKind::SurfaceNormal);
UVTK_MAP_BENCHMARKS(sphere_normal, SurfaceKind::Sphere, RayKind::ObjectNormal);
UVTK_MAP_BENCHMARKS(sphere_reflection, SurfaceKind::Sphere, RayKind::Reflection);
BENCHMARK_CAPTURE(project, cube_isn, SurfaceKind::Cube, RayKind::SurfaceNormal)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
