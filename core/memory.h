// The memory a process may still take, and sizes as people read them: for the checks that refuse
// work the machine cannot hold before anything is allocated (render frames, maps of huge meshes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

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

// "5.0 GiB", "12.3 MiB", "64.0 KiB", "512 bytes".
std::string formatBytes(std::uint64_t bytes);

}  // namespace uvtk
