// Mapping throughput on a 2048 x 1024 lat-long sphere (2.1 M vertices), single-threaded. The
// per-vertex mapping for every projector, precision and math mode is `uvtk bench`; here:
// - project: the whole job of `uvtk map` short of file I/O: placement fit, per-corner UVs,
//   pole and seam repair, summary.
// - atan2: the arctangent alone over the sphere's (y, x) in each precision and math mode
//   (param::atan2Block), the cost that dominates the sphere and cylinder.
// - kernel: the narrow kernel (param::mapUvs) on local points made once outside the timing, and
//   mapVertices (the move to the local frame, the kernel, the wide records) on 1 and 2 threads.
// `per_vertex` is seconds per vertex, printed with an SI prefix: "12.3n" is 12.3 ns.
#include <benchmark/benchmark.h>

#include <string>
#include <type_traits>
#include <vector>

#include "meshes/generators.h"
#include "param/batch_atan2.h"
#include "param/projector.h"
#include "param/surfaces.h"
#include "param/uv_kernel.h"

namespace {

using namespace uvtk;
using param::ProjectorOptions;
using param::RayKind;
using param::SurfaceKind;

const Mesh& sphere() {
  static const Mesh mesh = meshes::latLongSphere(2048, 1024);
  return mesh;
}

void setPerVertex(benchmark::State& state, std::size_t vertices) {
  state.counters["per_vertex"] = benchmark::Counter(
      static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void project(benchmark::State& state, SurfaceKind surface, RayKind ray) {
  const Mesh& mesh = sphere();
  param::ProjectorOptions options;
  options.surface = surface;
  options.ray = ray;
  for (auto _ : state) {
    param::Projection p = param::project(mesh, options);
    benchmark::DoNotOptimize(p.uv.uv.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

template <class T>
void atan2OverTheSphere(benchmark::State& state, MathMode math) {
  const Mesh& mesh = sphere();
  std::vector<T> y(mesh.vertexCount()), x(mesh.vertexCount()), angles(mesh.vertexCount());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = T(mesh.positions[i].y()), x[i] = T(mesh.positions[i].x());
  for (auto _ : state) {
    param::atan2Block(math, y.data(), x.data(), angles.data(), angles.size());
    benchmark::DoNotOptimize(angles.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

void atan2_double(benchmark::State& state, MathMode math) { atan2OverTheSphere<double>(state, math); }
void atan2_float(benchmark::State& state, MathMode math) { atan2OverTheSphere<float>(state, math); }

ProjectorOptions kernelOptions(SurfaceKind surface, Precision precision, MathMode math) {
  param::ProjectorOptions options;
  options.surface = surface;
  options.arithmetic = {precision, math};
  return options;
}

template <class T>
void narrowKernel(benchmark::State& state, SurfaceKind surface, MathMode math) {
  const Mesh& mesh = sphere();
  const param::ProjectorOptions options =
      kernelOptions(surface, std::is_same_v<T, float> ? Precision::Float : Precision::Double, math);
  const Affine3 frame = param::fitPlacement(mesh.positions, surface, options.placement);
  param::LocalPoints<T> points;
  param::toLocal(frame, mesh.positions, {}, points);
  param::UvArrays<T> out;
  param::mapUvs(options, frame, points, out);  // pages the output in
  for (auto _ : state) {
    param::mapUvs(options, frame, points, out, int(state.range(0)));
    benchmark::DoNotOptimize(out.u.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

void kernel_float(benchmark::State& state, SurfaceKind surface, MathMode math) {
  narrowKernel<float>(state, surface, math);
}
void kernel_double(benchmark::State& state, SurfaceKind surface, MathMode math) {
  narrowKernel<double>(state, surface, math);
}

void map_vertices(benchmark::State& state, SurfaceKind surface, Precision precision, MathMode math) {
  const Mesh& mesh = sphere();
  const param::ProjectorOptions options = kernelOptions(surface, precision, math);
  const Affine3 frame = param::fitPlacement(mesh.positions, surface, options.placement);
  std::vector<param::VertexUv> out;
  const param::Projector projector(options, frame);
  projector.mapVertices(mesh.positions, {}, out);
  for (auto _ : state) {
    projector.mapVertices(mesh.positions, {}, out, int(state.range(0)));
    benchmark::DoNotOptimize(out.data());
  }
  setPerVertex(state, mesh.vertexCount());
}

BENCHMARK_CAPTURE(atan2_double, exact, MathMode::Exact)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(atan2_double, fast, MathMode::Fast)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(atan2_double, fast_u10, MathMode::FastU10)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(atan2_float, exact, MathMode::Exact)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(atan2_float, fast, MathMode::Fast)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(atan2_float, fast_u10, MathMode::FastU10)->Unit(benchmark::kMillisecond);

// The kernel and mapVertices of every surface that maps per vertex, in both precisions and, where
// an arctangent makes the math mode matter (a wrapping surface), exact and fast; project() of every
// surface with a formula of a point. Taken from the surface list, so a new surface is timed too.
void registerPerSurface() {
  for (const SurfaceKind surface : param::kSurfaces) {
    if (!param::hasPointFormula(surface)) continue;
    const param::SurfaceTraits& traits = param::traitsOf(surface);
    const std::string name = traits.name;
    benchmark::RegisterBenchmark(("project/" + name + "_isn").c_str(), project, surface, RayKind::SurfaceNormal)
        ->Unit(benchmark::kMillisecond);
    if (traits.choosesPerTriangle) continue;  // the kernel maps vertices: no face to choose by
    for (const MathMode math : {MathMode::Exact, MathMode::Fast}) {
      if (math == MathMode::Fast && !traits.wraps) continue;
      const std::string mode = math == MathMode::Exact ? "_exact" : "_fast";
      benchmark::RegisterBenchmark(("kernel_double/" + name + mode).c_str(), kernel_double, surface, math)
          ->Arg(1)->Arg(2)->UseRealTime();
      benchmark::RegisterBenchmark(("kernel_float/" + name + mode).c_str(), kernel_float, surface, math)
          ->Arg(1)->Arg(2)->UseRealTime();
      benchmark::RegisterBenchmark(("map_vertices/" + name + "_double" + mode).c_str(), map_vertices, surface,
                                   Precision::Double, math)
          ->Arg(1)->Arg(2)->UseRealTime();
      benchmark::RegisterBenchmark(("map_vertices/" + name + "_float" + mode).c_str(), map_vertices, surface,
                                   Precision::Float, math)
          ->Arg(1)->Arg(2)->UseRealTime();
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  registerPerSurface();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
