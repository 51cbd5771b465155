// The memory a process may still take, and sizes as people read them: for the checks that refuse
// work the machine cannot hold before anything is allocated (render frames, maps of huge meshes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace uvtk {

// The bytes a process may still allocate: the least of MemAvailable (/proc/meminfo; else the
// free physical pages) and, when RLIMIT_AS is set, that limit less the address space in use
// (VmSize in /proc/self/status). Nothing when neither can be read.
std::optional<std::uint64_t> availableMemory();

// "5.0 GiB", "12.3 MiB", "64.0 KiB", "512 bytes".
std::string formatBytes(std::uint64_t bytes);

}  // namespace uvtk
