#pragma once

#include <filesystem>
#include <string_view>

namespace mechanist {

/// Writes `content` to `path` through a temporary file in the same folder and a rename, so
/// that a reader never sees a partial file and a failure leaves no file behind. Refuses to
/// write over `protect` (the input), and throws InputError naming the path on failure.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view content,
                         const std::filesystem::path& protect = {});

}  // namespace mechanist
