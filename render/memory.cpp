#include "render/memory.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/parallel.h"
#include "render/fragment_simd.h"
#include "render/raster.h"

namespace uvtk::render {

namespace {

std::uint64_t textureBytes(const Texture& texture) {
  std::uint64_t bytes = 0;
  const std::uint64_t perTexel = sizeof(Rgba) + (texture.packed() ? sizeof(std::uint32_t) : 0);
  for (int k = 0; k < texture.levelCount(); ++k) bytes += std::uint64_t(texture.level(k).texels.size()) * perTexel;
  return bytes;
}

}  // namespace

MemoryEstimate estimateMemory(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& o) {
  const auto n = std::uint64_t(std::lround(std::sqrt(double(std::clamp(o.samplesPerPixel, 1, 256)))));
  const std::uint64_t pixels = std::uint64_t(o.camera.width) * std::uint64_t(o.camera.height);
  const std::uint64_t aovBytes = o.aovs ? (o.cubeTexture ? 6 : 5) * sizeof(float) : 0;
  const std::uint64_t colourBytes = 3 * sizeof(float);
  const std::uint64_t coverageBytes = n > 1 ? 1 : 0;  // which samples a triangle covers, for the box filter
  MemoryEstimate e;
  e.frame = pixels * n * n * (coverageBytes + colourBytes + aovBytes);
  if (n > 1) e.frame += pixels * (colourBytes + aovBytes);  // the resolved frame
  const std::uint64_t faces = mesh.triangles.size();
  e.frame += mesh.positions.size() * (sizeof(Vec4) + 12);  // clip positions, snapped window positions
  e.frame += faces * 240;  // a drawn triangle's set-up with its face's interpolator (152 bytes), its tile index, growth
  e.frame += std::uint64_t(threadCount(o.raster.threads)) * (sizeof(TiledRaster::Tile) + sizeof(FragmentBatch));  // per thread: a tile in work and its fragments
  const bool lit = readsFragmentColour(o.env);
  if (lit || (source.pixelMapping && source.pixelMapping->needsNormal)) e.frame += 3 * faces * sizeof(Vec3);
  if (lit) e.frame += 3 * faces * sizeof(Vec4);
  if (o.texture) e.texture = textureBytes(*o.texture);
  if (source.pixelMapping && source.pixelMapping->blendAt)
    for (const Texture* t : o.axisTextures)
      if (t && t != o.texture) e.texture += textureBytes(*t);
  if (o.cubeTexture)
    for (int f = 0; f < kCubeFaceCount; ++f) e.texture += textureBytes(o.cubeTexture->face(CubeFace(f)));
  return e;
}

void checkMemory(const MemoryEstimate& estimate, std::uint64_t available, const std::string& what) {
  if (estimate.frame <= available) return;
  throw UsageError(what + " needs about " + formatBytes(estimate.frame) + " of memory for its buffers, more than the " +
                   formatBytes(available) + " available (the texture, loaded, takes " + formatBytes(estimate.texture) +
                   "); use a smaller --size or --spp");
}

}  // namespace uvtk::render
