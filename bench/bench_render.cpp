// Rendering throughput: a 1 M-triangle textured sphere at 1920 x 1080, trilinear filtering
// (LINEAR_MIPMAP_LINEAR, REPEAT), texture environment REPLACE, back faces culled.
// - render/uvtk: a render::Renderer's frames with RasterOptions::threads 1 and 2 (rasterisation and
//   shading; its buffers kept from frame to frame, as the GL context keeps its framebuffer and bins);
//   counters rasterMs and shadeMs are the Rendering's own split, coveredPixels the pixels shaded.
// - render/llvmpipe: the same scene through Mesa's OSMesa (clear + draw from VBOs + glFinish; no
//   read-back, OSMesa draws into our memory), LP_NUM_THREADS 0 (rasterised in the calling
//   thread), 1 and 2, each in a child process; the label is GL_RENDERER.
// Times are ms per frame. cpuMs is the process CPU time per frame over all its threads (the CPU
// column counts only the benchmark's own thread, and for llvmpipe not the child at all).
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <benchmark/benchmark.h>
#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "meshes/generators.h"
#include "render/procedural.h"
#include "render/renderer.h"

namespace {

using namespace uvtk;

constexpr int kWidth = 1920, kHeight = 1080;
constexpr double kRepeatsS = 8.0, kRepeatsT = 4.0;  // enough texels per pixel that trilinear minifies

struct Scene {
  Scene() {
    texcoords.corners = meshes::latLongCornerTexcoords(mesh, kRepeatsS, kRepeatsT);
    texture.buildMipmaps();
    options.camera = render::frameSphere(render::boundingSphere(mesh.positions), Vec3(1, -2, 0.8), Vec3(0, 0, 1), {},
                                         kWidth, kHeight);
    options.raster.cull = render::Cull::Back;
    options.texture = &texture;
    options.sampler = render::samplerFor(render::Filter::LinearMipmapLinear, render::Wrap::Repeat);
    options.env = render::EnvMode::Replace;
  }
  Scene(const Scene&) = delete;  // options points at texture

  Mesh mesh = meshes::latLongSphere(1024, 513);  // 2 * 1024 * 512 = 1,048,576 triangles
  render::TexcoordSource texcoords;
  render::Texture texture = render::checkerTexture(1024, 32);
  render::RenderOptions options;
};

const Scene& scene() {
  static const Scene s;
  return s;
}

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

void setAverages(benchmark::State& state, const char* name, double sum) {
  state.counters[name] = benchmark::Counter(sum, benchmark::Counter::kAvgIterations);
}

void uvtkRender(benchmark::State& state) {
  const Scene& s = scene();
  render::RenderOptions options = s.options;
  options.raster.threads = int(state.range(0));
  double rasterMs = 0.0, shadeMs = 0.0, cpuMs = 0.0;
  std::size_t covered = 0;
  render::Renderer renderer;  // its buffers kept between frames, as llvmpipe's context keeps its own
  for (auto _ : state) {
    const double cpuStart = processCpuMs();
    const render::Rendering& r = renderer.render(s.mesh, s.texcoords, options);
    cpuMs += processCpuMs() - cpuStart;
    rasterMs += r.rasterMs;
    shadeMs += r.shadeMs;
    covered = r.coveredPixels;
    benchmark::DoNotOptimize(r.colour.pixels.data());
  }
  setAverages(state, "rasterMs", rasterMs);
  setAverages(state, "shadeMs", shadeMs);
  setAverages(state, "cpuMs", cpuMs);
  state.counters["coveredPixels"] = double(covered);
}

// ---- Mesa ----------------------------------------------------------------------------------

bool readAll(int fd, void* data, std::size_t size) {
  auto* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = read(fd, p, size);
    if (n <= 0) return false;
    p += n, size -= std::size_t(n);
  }
  return true;
}

bool writeAll(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = write(fd, p, size);
    if (n <= 0) return false;
    p += n, size -= std::size_t(n);
  }
  return true;
}

int processThreads() {
  int n = 0;
  if (DIR* d = opendir("/proc/self/task")) {
    while (const dirent* e = readdir(d)) n += e->d_name[0] != '.';
    closedir(d);
  }
  return n;
}

struct MesaHello {
  char renderer[128] = {};  // empty when no context could be made
  int threads = 0;          // the child's threads once the context exists: shows LP_NUM_THREADS took
  long coveredPixels = 0;   // depth below 1 after one frame
};

struct MesaFrame {
  double wallMs = 0.0, cpuMs = 0.0;
};

// Everything GL, run in the child: the scene uploaded once (mip levels as RGBA8, corners in VBOs),
// one frame to compile llvmpipe's shaders, then a frame per byte read from `in`.
void mesaChild(int in, int out) {
  const Scene& s = scene();
  MesaHello hello;
  std::vector<unsigned char> colour(std::size_t(kWidth) * kHeight * 4);
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context || !OSMesaMakeCurrent(context, colour.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
    writeAll(out, &hello, sizeof hello);
    return;
  }
  std::strncpy(hello.renderer, reinterpret_cast<const char*>(glGetString(GL_RENDERER)), sizeof hello.renderer - 1);

  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(s.options.camera.clipFromView.data());
  glMatrixMode(GL_MODELVIEW);
  const Mat4 modelview = s.options.camera.viewFromWorld * s.options.worldFromObject;
  glLoadMatrixd(modelview.data());
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);  // GL_BACK, front faces counter-clockwise: the defaults, as in uvtk

  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  for (int k = 0; k < s.texture.levelCount(); ++k) {
    const render::TexelLevel& level = s.texture.level(k);
    std::vector<unsigned char> texels;
    texels.reserve(4 * level.texels.size());
    for (const render::Rgba& t : level.texels)
      for (int c = 0; c < 4; ++c) texels.push_back(static_cast<unsigned char>(std::lround(255.0f * t[c])));
    glTexImage2D(GL_TEXTURE_2D, k, GL_RGBA8, level.width, level.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);

  // Unindexed corners, as uvtk reads them: per-corner texture coordinates split the vertices anyway.
  std::vector<GLfloat> positions, texcoords;
  positions.reserve(9 * s.mesh.faceCount());
  texcoords.reserve(6 * s.mesh.faceCount());
  for (std::size_t f = 0; f < s.mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = s.mesh.positions[std::size_t(s.mesh.triangles[f][k])];
      const Vec4& t = s.texcoords.corners[3 * f + std::size_t(k)];
      positions.insert(positions.end(), {GLfloat(p.x()), GLfloat(p.y()), GLfloat(p.z())});
      texcoords.insert(texcoords.end(), {GLfloat(t.x()), GLfloat(t.y())});
    }
  GLuint buffers[2] = {};
  glGenBuffers(2, buffers);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(positions.size() * sizeof(GLfloat)), positions.data(), GL_STATIC_DRAW);
  glVertexPointer(3, GL_FLOAT, 0, nullptr);
  glBindBuffer(GL_ARRAY_BUFFER, buffers[1]);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(texcoords.size() * sizeof(GLfloat)), texcoords.data(), GL_STATIC_DRAW);
  glTexCoordPointer(2, GL_FLOAT, 0, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  const GLsizei cornerCount = GLsizei(3 * s.mesh.faceCount());

  auto frame = [&] {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, cornerCount);
    glFinish();
  };
  frame();
  std::vector<GLfloat> depth(std::size_t(kWidth) * kHeight);
  glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  for (GLfloat d : depth) hello.coveredPixels += d < 1.0f;
  hello.threads = processThreads();
  if (!writeAll(out, &hello, sizeof hello)) return;

  char request = 0;
  while (readAll(in, &request, 1)) {
    MesaFrame times;
    const double cpuStart = processCpuMs();
    const auto start = std::chrono::steady_clock::now();
    frame();
    times.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    times.cpuMs = processCpuMs() - cpuStart;
    if (!writeAll(out, &times, sizeof times)) break;
  }
  OSMesaDestroyContext(context);
}

// llvmpipe reads LP_NUM_THREADS once per process, when the first context creates its screen, so
// each thread count renders in a child process of its own; this process never touches GL. The
// child measures each frame itself and the benchmark takes that as the iteration's time.
void mesaRender(benchmark::State& state) {
  scene();  // built before the fork, so that every child inherits it
  int toChild[2], toParent[2];
  if (pipe(toChild) != 0 || pipe(toParent) != 0) {
    state.SkipWithError("pipe failed");
    return;
  }
  const pid_t child = fork();
  if (child == 0) {
    close(toChild[1]);
    close(toParent[0]);
    setenv("LP_NUM_THREADS", std::to_string(state.range(0)).c_str(), 1);
    mesaChild(toChild[0], toParent[1]);
    _exit(0);  // no atexit handlers or static destructors of the benchmark in the child
  }
  close(toChild[0]);
  close(toParent[1]);
  MesaHello hello;
  const bool started = child > 0 && readAll(toParent[0], &hello, sizeof hello) && hello.renderer[0] != '\0';
  if (!started) {
    state.SkipWithError("no OSMesa context");
  } else {
    state.SetLabel(hello.renderer);
    double cpuMs = 0.0;
    for (auto _ : state) {
      const char request = 1;
      MesaFrame times;
      if (!writeAll(toChild[1], &request, 1) || !readAll(toParent[0], &times, sizeof times)) {
        state.SkipWithError("the Mesa child stopped");
        break;
      }
      state.SetIterationTime(1e-3 * times.wallMs);
      cpuMs += times.cpuMs;
    }
    setAverages(state, "cpuMs", cpuMs);
    state.counters["coveredPixels"] = double(hello.coveredPixels);
    state.counters["processThreads"] = hello.threads;
  }
  close(toChild[1]);  // end of input: the child leaves its loop
  close(toParent[0]);
  if (child > 0) waitpid(child, nullptr, 0);
}

// Frames for --benchmark_min_time seconds each (0.5 s by default, 5 to 10 frames); the scene is
// built once, in about 3 s.
BENCHMARK(uvtkRender)->Name("render/uvtk")->ArgName("threads")->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(mesaRender)
    ->Name("render/llvmpipe")
    ->ArgName("LP_NUM_THREADS")
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
