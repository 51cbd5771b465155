// Mapping::at() does not allocate (uvtk/point.h promises it): this file replaces the program's global
// operator new (every form) with a counting one and, with glibc outside the sanitizers (which own
// malloc), malloc and its family too, so that Eigen's or anyone's direct malloc inside
// libuvtk_point.so is seen as well. The counters only count while a test switches them on.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <string>
#include <vector>

#include "uvtk/point.h"

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer) || \
    __has_feature(hwaddress_sanitizer)
#define UVTK_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define UVTK_TEST_SANITIZED 1
#endif
#if defined(__GLIBC__) && !defined(UVTK_TEST_SANITIZED)
#define UVTK_TEST_COUNT_MALLOC 1
#endif

namespace {

std::atomic<bool> counting{false};
std::atomic<long> newCalls{0}, mallocCalls{0};

void noteNew() {
  if (counting.load(std::memory_order_relaxed)) newCalls.fetch_add(1, std::memory_order_relaxed);
}

void* allocate(std::size_t n) {
  noteNew();
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}

void* allocateAligned(std::size_t n, std::align_val_t alignment) {
  noteNew();
  const std::size_t a = static_cast<std::size_t>(alignment);
  if (void* p = std::aligned_alloc(a, (n + a - 1) / a * a + (n ? 0 : a))) return p;
  throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  noteNew();
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  noteNew();
  return std::malloc(n ? n : 1);
}
void* operator new(std::size_t n, std::align_val_t a) { return allocateAligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocateAligned(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

#ifdef UVTK_TEST_COUNT_MALLOC
// glibc's documented way to replace malloc: define the family, here forwarding to glibc's own.
extern "C" {
void* __libc_malloc(std::size_t);
void __libc_free(void*);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
}

namespace {
void noteMalloc() {
  if (counting.load(std::memory_order_relaxed)) mallocCalls.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) noexcept {
  noteMalloc();
  return __libc_malloc(n);
}
void free(void* p) noexcept { __libc_free(p); }
void* calloc(std::size_t count, std::size_t n) noexcept {
  noteMalloc();
  return __libc_calloc(count, n);
}
void* realloc(void* p, std::size_t n) noexcept {
  noteMalloc();
  return __libc_realloc(p, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) noexcept {
  noteMalloc();
  return __libc_memalign(alignment, n);
}
void* memalign(std::size_t alignment, std::size_t n) noexcept {
  noteMalloc();
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) noexcept {
  noteMalloc();
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, n);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
}
#endif

namespace {
namespace UVTK_TEST_FILE {

using uvtk::point::Mapping;
using uvtk::point::Result;
using uvtk::point::Vector3;

struct Counts {
  long news, mallocs;
};

template <class F>
Counts countDuring(F&& f) {
  newCalls = 0;
  mallocCalls = 0;
  counting = true;
  f();
  counting = false;
  return {newCalls.load(), mallocCalls.load()};
}

TEST(NoAllocation, AtAllocatesNothing) {
  const std::vector<Vector3> mesh = {{-1, -2, -3}, {2, 1, 4}, {0.5, 0.25, -1}, {1, -1, 0}};
  std::vector<Mapping> mappings;
  for (const char* options :
       {"--projector sphere", "--projector sphere --omap normal", "--projector sphere --omap centroid",
        "--projector sphere --omap reflection --eye 0,0,5",
        "--projector sphere --omap reflection --eye 0,0,5 --at-infinity", "--projector cylinder --caps",
        "--projector cylinder --omap normal --uv-scale 2,1 --uv-rotate 30", "--projector cube",
        "--projector cube --cube-layout cross --omap normal", "--projector plane",
        "--projector two-plane --omap centroid", "--projector sphere --sphere-preset seed004 --precision float",
        "--projector sphere --math fast", "--texgen sphere_map", "--texgen reflection_map --eye 0,0,5 --center 0,0,0",
        "--texgen normal_map --model \"2 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1\"",
        "--s eye_linear:1,0,0,0 --t object_linear:0,1,0,1 --q object_linear:0,0,1,2 --texmatrix \"1 0 0 0 0 1 0 0 0 0 "
        "1 "
        "0 0.5 0 0 1\""})
    mappings.emplace_back(options);
  mappings.emplace_back("--projector sphere --convention blender", mesh);
  mappings.emplace_back("--projector cylinder --convention assimp", mesh);
  mappings.emplace_back("--projector cube --fit obb", mesh);

  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vector3> points = {{0, 0, 0},  {0, 0, 1},   {0, 0, -1},  {1, 0, 0},         {1, -0.0, 0},
                                 {-1, 0, 0}, {nan, 0, 0}, {inf, 1, 1}, {1e300, 1e300, 1}, {1e-300, 0, 1}};
  for (int i = 0; i < 200; ++i)
    points.push_back({std::cos(i * 0.37) * (1 + i % 3), std::sin(i * 0.37) * (1 + i % 5), std::cos(i * 0.11) * 2});
  const Vector3 normals[] = {{0, 0, 0}, {0, 0, 1}, {1, 2, 3}, {-1, 0, 0}, {nan, 0, 0}};

  double sum = 0;
  int evaluated = 0;
  const Counts counts = countDuring([&] {
    for (const Mapping& m : mappings)
      for (const Vector3& p : points)
        for (const Vector3& n : normals) {
          const Result r = m.at(p, n);
          sum += r.u + r.v + r.w + r.q + static_cast<int>(r.status);
          ++evaluated;
        }
  });
  EXPECT_EQ(counts.news, 0) << "operator new calls during " << evaluated << " evaluations";
  EXPECT_EQ(counts.mallocs, 0) << "malloc calls during " << evaluated << " evaluations";
  EXPECT_TRUE(std::isfinite(sum));
  EXPECT_EQ(evaluated, 20 * 210 * 5);
}

// The counters see allocations, including those inside libuvtk_point.so.
TEST(NoAllocation, TheCountersSeeAllocations) {
  const Counts construction = countDuring([] { Mapping m("--projector sphere"); });
  EXPECT_GT(construction.news, 0);
  const Counts direct = countDuring([] {
    void* volatile p = std::malloc(64);
    std::free(p);
  });
#ifdef UVTK_TEST_COUNT_MALLOC
  EXPECT_GT(direct.mallocs, 0);
#else
  EXPECT_EQ(direct.mallocs, 0);
  GTEST_SKIP() << "malloc is the sanitizer's here: only operator new is counted";
#endif
}

}  // namespace UVTK_TEST_FILE
}  // namespace
