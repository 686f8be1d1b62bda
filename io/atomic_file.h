#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace mechanist {

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so
/// that a reader never sees a partial file and a failure leaves no file behind. Refuses to
/// write over `protect` (the input), and throws InputError naming the path on failure.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content,
                         const std::filesystem::path& protect = {});

/// The same for content too large to hold in memory: `write` streams it into the temporary
/// file. An exception from `write` removes the temporary file and propagates.
void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write,
                         const std::filesystem::path& protect = {});

}  // namespace mechanist
