#include "io/internal/memory_budget.h"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace mechanist::internal {

namespace {

// The value in kB of the line "key: value kB" of a /proc file, in bytes.
std::optional<std::uint64_t> ProcKilobytes(const char* file, std::string_view key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) != 0 || line.size() <= key.size() ||
        line[key.size()] != ':') {
      continue;
    }
    std::istringstream value(line.substr(key.size() + 1));
    std::uint64_t kilobytes = 0;
    if (value >> kilobytes) return kilobytes * 1024;
  }
  return std::nullopt;
}

// What the soft limit `resource` leaves above `used` bytes; nothing when unlimited.
std::optional<std::uint64_t> LeftUnderLimit(int resource, std::optional<std::uint64_t> used) {
  rlimit limit{};
  if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || !used) {
    return std::nullopt;
  }
  const auto cap = static_cast<std::uint64_t>(limit.rlim_cur);
  return cap > *used ? cap - *used : 0;
}

// Decimal units, as file sizes are given: a 200 GB file is 200e9 bytes.
std::string Bytes(std::uint64_t bytes) {
  const double mb = static_cast<double>(bytes) / 1e6;
  return mb >= 1000 ? fmt::format("{:.1f} GB", mb / 1000) : fmt::format("{:.0f} MB", mb);
}

}  // namespace

std::optional<std::uint64_t> AvailableMemoryBytes() {
  std::optional<std::uint64_t> available = ProcKilobytes("/proc/meminfo", "MemAvailable");
  for (const std::optional<std::uint64_t> left :
       {LeftUnderLimit(RLIMIT_AS, ProcKilobytes("/proc/self/status", "VmSize")),
        LeftUnderLimit(RLIMIT_DATA, ProcKilobytes("/proc/self/status", "VmData"))}) {
    if (left) available = available ? std::min(*available, *left) : *left;
  }
  return available;
}

std::uint64_t ReadingNeed(const std::filesystem::path& file, double bytes_per_file_byte) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return 0;
  const double need = std::ceil(static_cast<double>(size) * bytes_per_file_byte);
  constexpr auto kMax = static_cast<double>(std::numeric_limits<std::uint64_t>::max());
  return need >= kMax ? std::numeric_limits<std::uint64_t>::max()
                      : static_cast<std::uint64_t>(need);
}

std::optional<std::string> MemoryShortfall(std::uint64_t needed, std::string_view what) {
  const std::optional<std::uint64_t> available = AvailableMemoryBytes();
  if (!available || needed <= *available) return std::nullopt;
  return fmt::format("reading it needs about {} of memory ({}); {} are available", Bytes(needed),
                     what, Bytes(*available));
}

}  // namespace mechanist::internal
