#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

namespace mechanist {

/// Throws InputError naming `path` when an output file could not be written there: its folder
/// does not exist (or is no folder), or it is `protect`, the input. Commands check their
/// outputs so before any work, and AtomicOutput again when it writes.
void CheckOutputPath(const std::filesystem::path& path, const std::filesystem::path& protect = {});

/// An output file written under a temporary name in its folder and renamed into place by
/// Commit, for writers that need a file name (video encoders): a reader never sees a partial
/// file, and the temporary file is removed when the object dies uncommitted. Refuses (throws
/// InputError) to stand for `protect`, the input.
class AtomicOutput {
 public:
  AtomicOutput(const std::filesystem::path& path, const std::filesystem::path& protect = {});
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// Where to write until Commit.
  const std::filesystem::path& temporary() const { return temporary_; }
  /// Moves the temporary file into place; throws InputError naming the path when it is
  /// missing or cannot be moved.
  void Commit();

 private:
  std::filesystem::path path_, temporary_;
  bool committed_ = false;
};

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
