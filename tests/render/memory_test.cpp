// Memory before work: the estimate of a render against what render() really allocates (counted by
// a replaced operator new), the refusal message, and the memory the process may still take.
#include <gtest/gtest.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <new>

#include "core/error.h"
#include "core/gl_matrices.h"
#include "render/fragment_simd.h"
#include "render/memory.h"
#include "render/procedural.h"
#include "render/quad_fixture.h"

#if defined(__SANITIZE_ADDRESS__)
#define UVTK_COUNTING_NEW 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UVTK_COUNTING_NEW 0
#endif
#endif
#ifndef UVTK_COUNTING_NEW
#define UVTK_COUNTING_NEW 1  // the sanitizers bring their own operator new
#endif

namespace {

std::atomic<std::int64_t> gLive{0}, gPeak{0};

}  // namespace

#if UVTK_COUNTING_NEW
// Every allocation of the program goes through these while it runs; they count the bytes alive and
// their peak. The other forms of new and delete of libstdc++ call these, but for the over-aligned
// ones (a batch of fragments is aligned to 64 bytes), which are counted alike.
namespace {
void* counted(void* p) {
  if (!p) throw std::bad_alloc();
  const std::int64_t live = gLive += std::int64_t(malloc_usable_size(p));
  for (std::int64_t peak = gPeak; live > peak && !gPeak.compare_exchange_weak(peak, live);) {
  }
  return p;
}
}  // namespace
void* operator new(std::size_t size) { return counted(std::malloc(size ? size : 1)); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  const auto a = static_cast<std::size_t>(alignment);
  return counted(std::aligned_alloc(a, (std::max<std::size_t>(size, 1) + a - 1) / a * a));
}
void operator delete(void* p, std::align_val_t) noexcept {
  if (p) gLive -= std::int64_t(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  if (p) gLive -= std::int64_t(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p) noexcept {
  if (p) gLive -= std::int64_t(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  if (p) gLive -= std::int64_t(malloc_usable_size(p));
  std::free(p);
}
#endif

namespace uvtk::render {
namespace {
namespace UVTK_TEST_FILE {

RenderOptions quadOptions(const Texture& texture, int width, int height) {
  RenderOptions o;
  o.camera.width = width;
  o.camera.height = height;
  o.camera.clipFromView = orthographic(-1, 1, -1, 1, -1, 1);
  o.texture = &texture;
  return o;
}

TEST(MemoryEstimate, IsWhatRenderAllocatesAtItsPeak) {
  if (!UVTK_COUNTING_NEW) GTEST_SKIP() << "allocations are not counted under the sanitizers";
  const Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  Texture texture = checkerTexture(64, 4);
  texture.buildMipmaps();
  for (const auto& [spp, aovs] : {std::pair{1, false}, std::pair{1, true}, std::pair{16, true}, std::pair{9, false}}) {
    RenderOptions o = quadOptions(texture, 300, 200);
    o.samplesPerPixel = spp;
    o.aovs = aovs;
    o.raster.threads = 2;
    const MemoryEstimate estimate = estimateMemory(quad.mesh, quad.texcoords, o);
    // By hand: the n x n larger frame's coverage (with supersampling), RGB and AOVs; the resolved RGB and AOVs.
    const std::uint64_t samples = 300 * 200 * std::uint64_t(spp), pixels = 300 * 200;
    const std::uint64_t aovBytes = aovs ? 20 : 0;
    EXPECT_EQ(estimate.frame, samples * ((spp > 1 ? 1 : 0) + 12 + aovBytes) + (spp > 1 ? pixels * (12 + aovBytes) : 0) +
                                  4 * (sizeof(Vec4) + 12) + 2 * 240 + 2 * (sizeof(TiledRaster::Tile) + sizeof(FragmentBatch)));
    // Float RGBA and the 8-bit checker's packed bytes: 16 + 4 bytes a texel.
    EXPECT_EQ(estimate.texture, 20u * (64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1));

    const std::int64_t before = gLive;
    gPeak = before;
    {
      const Rendering r = render(quad.mesh, quad.texcoords, o);
      ASSERT_EQ(r.colour.width, 300);
    }
    const double peak = double(gPeak - before);
    EXPECT_GT(peak, 0.97 * double(estimate.frame)) << "spp " << spp << " aovs " << aovs;
    EXPECT_LT(peak, 1.05 * double(estimate.frame)) << "spp " << spp << " aovs " << aovs;
  }
}

TEST(MemoryEstimate, LitFramesCountTheirCornerNormalsAndColours) {
  const Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  const Texture texture = checkerTexture(8, 2);
  RenderOptions o = quadOptions(texture, 10, 10);
  const std::uint64_t unlit = estimateMemory(quad.mesh, quad.texcoords, o).frame;
  o.env = EnvMode::Modulate;
  EXPECT_EQ(estimateMemory(quad.mesh, quad.texcoords, o).frame, unlit + 6 * (sizeof(Vec3) + sizeof(Vec4)));
}

TEST(MemoryEstimate, ARenderBeyondTheAvailableMemoryIsRefusedNamingBoth) {
  MemoryEstimate e;
  e.frame = std::uint64_t(5) << 30;
  e.texture = std::uint64_t(1) << 29;
  EXPECT_NO_THROW(checkMemory(e, e.frame, "rendering 16384x16384"));
  try {
    checkMemory(e, std::uint64_t(3) << 30, "rendering 16384x16384");
    ADD_FAILURE() << "accepted";
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(),
                 "rendering 16384x16384 needs about 5.0 GiB of memory for its buffers, more than the 3.0 GiB "
                 "available (the texture, loaded, takes 512.0 MiB); use a smaller --size or --spp");
  }
  EXPECT_EQ(formatBytes(1023), "1023 bytes");
  EXPECT_EQ(formatBytes(65536), "64.0 KiB");
  EXPECT_EQ(formatBytes(std::uint64_t(3) << 19), "1.5 MiB");
}

// The address space in use, from /proc/self/status.
std::uint64_t vmSize() {
  std::ifstream status("/proc/self/status");
  std::string word;
  std::uint64_t kilobytes = 0;
  while (status >> word)
    if (word == "VmSize:") status >> kilobytes;
  return kilobytes * 1024;
}

// Runs `f` with the address space limited to what is in use plus `room` bytes.
template <class F>
void withAddressSpaceRoom(std::uint64_t room, F&& f) {
  rlimit old{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &old), 0);
  rlimit tight = old;
  tight.rlim_cur = vmSize() + room;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  f();
  ASSERT_EQ(setrlimit(RLIMIT_AS, &old), 0);
}

bool addressSpaceUnlimited() {
  rlimit limit{};
  return getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
}

TEST(MemoryEstimate, RenderRefusesAFrameTheProcessCannotHoldBeforeAllocatingIt) {
  // The sanitizers reserve terabytes of address space, which no tight limit allows.
  if (!UVTK_COUNTING_NEW || !addressSpaceUnlimited()) GTEST_SKIP() << "sanitized, or the address space is limited";
  const Quad quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0));
  const Texture texture = checkerTexture(8, 2);
  RenderOptions o = quadOptions(texture, 16384, 16384);  // 3.0 GiB of buffers (the float RGB image)
  withAddressSpaceRoom(std::uint64_t(1) << 30, [&] {
    try {
      render(quad.mesh, quad.texcoords, o);
      ADD_FAILURE() << "accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("rendering 16384x16384 needs about 3.0 GiB of memory"), std::string::npos)
          << e.what();
    }
  });
}

TEST(AvailableMemory, IsAtMostWhatTheAddressSpaceLimitLeaves) {
  const std::optional<std::uint64_t> unlimited = availableMemory();
  ASSERT_TRUE(unlimited);
  EXPECT_GT(*unlimited, 0u);
  if (!UVTK_COUNTING_NEW || !addressSpaceUnlimited()) GTEST_SKIP() << "sanitized, or the address space is limited";
  std::optional<std::uint64_t> limited;
  withAddressSpaceRoom(std::uint64_t(64) << 20, [&] { limited = availableMemory(); });
  ASSERT_TRUE(limited);
  EXPECT_LE(*limited, std::uint64_t(64) << 20);
  EXPECT_GT(*limited, std::uint64_t(32) << 20);
}

}  // namespace UVTK_TEST_FILE
}  // namespace
}  // namespace uvtk::render
