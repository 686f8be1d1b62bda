#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace mechanist::internal {

/// The memory loading a file takes per byte of it, at most, as measured by the peak resident
/// size of `mechanist validate` above that of `mechanist --version` (README, "Resource
/// bounds"): a binary STL of a million triangles 6.5 (reading alone 2.7), Open CASCADE's model
/// of a STEP file with its tessellation 18.4 on the largest real exports, an assembly file's
/// parsed JSON with the position of every value and its parts 15.2 (60,000 parts).
inline constexpr double kMeshBytesPerFileByte = 7;
inline constexpr double kStepBytesPerFileByte = 20;
inline constexpr double kJsonBytesPerFileByte = 20;

/// Bytes this process can still take: the kernel's estimate of the memory available without
/// swapping (MemAvailable in /proc/meminfo), or less where the soft limit on the address space
/// (ulimit -v) or the data segment (ulimit -d) leaves less above what the process uses
/// already (VmSize, VmData in /proc/self/status). Nothing when none of them can be read.
std::optional<std::uint64_t> AvailableMemoryBytes();

/// The memory reading `file` takes at most, as measured (README, "Resource bounds"): the
/// file's bytes times `bytes_per_file_byte`, the file itself included.
std::uint64_t ReadingNeed(const std::filesystem::path& file, double bytes_per_file_byte);

/// When `needed` bytes are more than AvailableMemoryBytes(): what to tell the user, e.g.
/// "reading it needs about 7.0 GB of memory (a mesh file); 1.5 GB are available" (decimal
/// units), without the file's name (the caller's error names it); `what` is the parenthesis.
/// Nothing when it fits.
std::optional<std::string> MemoryShortfall(std::uint64_t needed, std::string_view what);

}  // namespace mechanist::internal
