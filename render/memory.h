// Memory before work: what a render will allocate, estimated from its options before anything is
// allocated, and what the machine can give. A 16384 x 16384 frame takes 5 GiB of buffers; without
// the check it ran into swap or the OOM killer with no word.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/memory.h"
#include "render/renderer.h"

namespace uvtk::render {

struct MemoryEstimate {
  // What render() allocates: per sample of the (supersampled) frame the colour, the AOVs and, with
  // supersampling, a coverage byte; the resolved frame; per vertex the clip and snapped window
  // positions; per face the set-up triangles; a tile and a batch of fragments per thread; per
  // corner the normals and lit colours when something reads them.
  std::uint64_t frame = 0;
  // The bound texture with every level it holds, as floats and packed (already in memory when
  // render() is called), and a blend's other axis textures.
  std::uint64_t texture = 0;
  std::uint64_t total() const { return frame + texture; }
};

// The estimate for render(mesh, source, options) with valid arguments.
MemoryEstimate estimateMemory(const Mesh& mesh, const TexcoordSource& source, const RenderOptions& options);

// Throws UsageError naming `what`, the estimate and the available memory when the memory still to
// be allocated (the frame's) exceeds `available`.
void checkMemory(const MemoryEstimate& estimate, std::uint64_t available, const std::string& what);

}  // namespace uvtk::render
