// The cost of one texture lookup: a 2D texture against a cube map (face selection, per-face
// filtering) and the seamless mode (texels across face edges), per filter. docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "render/cube_texture.h"
#include "render/procedural.h"
#include "render/texture.h"

namespace {

using namespace uvtk;
using namespace uvtk::render;

constexpr int kLookups = 1 << 16;

// Uniformly distributed unit directions.
std::vector<Vec3> directions() {
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  std::vector<Vec3> out(kLookups);
  for (Vec3& d : out) d = Vec3(normal(random), normal(random), normal(random)).normalized();
  return out;
}

void flatLookup(benchmark::State& state, Filter filter) {
  Texture texture = checkerTexture(256, 8);
  texture.buildMipmaps();
  const SamplerState sampler = samplerFor(filter, Wrap::Repeat);
  const std::vector<Vec3> d = directions();
  for (auto _ : state) {
    Vec4 sum = Vec4::Zero();
    for (const Vec3& v : d) sum += sample(texture, sampler, 0.5 * v.x() + 0.5, 0.5 * v.y() + 0.5, 1.5);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kLookups);
}

void cubeLookup(benchmark::State& state, Filter filter, bool seamless) {
  CubeTexture texture = cubeCheckerTexture(256);
  texture.buildMipmaps();
  const SamplerState sampler = samplerFor(filter, Wrap::ClampToEdge);
  const std::vector<Vec3> d = directions();
  for (auto _ : state) {
    Vec4 sum = Vec4::Zero();
    for (const Vec3& v : d) {
      const CubeCoordinates c = cubeCoordinates(v);
      sum += sampleCube(texture, sampler, c.face, c.st.x(), c.st.y(), 1.5, seamless);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kLookups);
}

}  // namespace

BENCHMARK_CAPTURE(flatLookup, nearest, Filter::Nearest);
BENCHMARK_CAPTURE(flatLookup, linear, Filter::Linear);
BENCHMARK_CAPTURE(flatLookup, linear_mipmap_linear, Filter::LinearMipmapLinear);
BENCHMARK_CAPTURE(cubeLookup, nearest, Filter::Nearest, false);
BENCHMARK_CAPTURE(cubeLookup, linear, Filter::Linear, false);
BENCHMARK_CAPTURE(cubeLookup, linear_seamless, Filter::Linear, true);
BENCHMARK_CAPTURE(cubeLookup, linear_mipmap_linear, Filter::LinearMipmapLinear, false);
BENCHMARK_CAPTURE(cubeLookup, linear_mipmap_linear_seamless, Filter::LinearMipmapLinear, true);

BENCHMARK_MAIN();
