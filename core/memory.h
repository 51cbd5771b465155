// The memory a process may still take, and sizes as people read them: for the checks that refuse
// work the machine cannot hold before anything is allocated (render frames, maps of huge meshes).
// And what the C library does with memory freed: given back, or kept for the next mesh.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace uvtk {

// The bytes a process may still allocate: the least of MemAvailable (/proc/meminfo; else the
// free physical pages), the room its memory control groups leave (cgroupMemoryLeft) and, when
// RLIMIT_AS is set, that limit less the address space in use (VmSize in /proc/self/status).
// Nothing when none can be read.
std::optional<std::uint64_t> availableMemory();

// The least room left by the memory limits of the process's control group and of every group
// above it: cgroup v2's memory.max less memory.current, v1's memory.limit_in_bytes less
// memory.usage_in_bytes (each usage less memory.stat's inactive file pages, which the kernel
// reclaims before it fails an allocation), found through /proc/self/cgroup and /proc/self/mountinfo (a container
// sees its own group as the mount's root). Nothing when no group sets a limit. `root` is prefixed
// to every path read (tests build a tree of their own).
std::optional<std::uint64_t> cgroupMemoryLeft(const std::string& root = "");

// What glibc's malloc does with the memory a process frees (a no-op with other C libraries).
enum class FreedMemory {
  // Blocks of 1 MiB or more mapped on their own and unmapped when freed: a large mesh's stages
  // hand their memory back as they finish, which keeps the process's peak near its live data.
  GivenBack,
  // Blocks below 16 MiB taken from the heap, and up to 64 MiB of free heap kept: a process that
  // maps many meshes one after another reuses one mesh's memory for the next rather than giving
  // it back and having the kernel fault in and clear fresh pages again.
  KeptForReuse,
};
void setFreedMemory(FreedMemory policy);
// The policy for a process that maps meshes one after another, the largest file `largestBytes` long
// (nothing: a size that could not be read): kept for reuse up to 16 MiB, where a mesh's blocks are
// mostly below the mapping threshold; a larger mesh's stages would keep up to 120 MB more of them
// (the 4 M-face sphere twice in a batch: 520 to 643 MB), so a batch that holds one gives back.
FreedMemory freedMemoryForMeshes(std::optional<std::uint64_t> largestBytes);

// The size of the largest of the files at `paths` (0 for none); nothing when one cannot be read.
std::optional<std::uint64_t> largestFile(const std::vector<std::string>& paths);

// "5.0 GiB", "12.3 MiB", "64.0 KiB", "512 bytes".
std::string formatBytes(std::uint64_t bytes);

}  // namespace uvtk
