#include "io/atomic_file.h"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <system_error>

#include "io/input_error.h"

namespace mechanist {

void WriteFileAtomically(const std::filesystem::path& path, std::string_view content,
                         const std::filesystem::path& protect) {
  WriteFileAtomically(
      path,
      [content](std::ostream& out) {
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
      },
      protect);
}

void CheckOutputPath(const std::filesystem::path& path, const std::filesystem::path& protect) {
  std::error_code ec;
  if (!protect.empty() && std::filesystem::exists(path, ec) &&
      std::filesystem::equivalent(path, protect, ec)) {
    throw InputError(path.string(), "", 0, 0, "refusing to write over the input file");
  }
  const std::filesystem::path folder = path.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec)) {
    throw InputError(
        path.string(), "", 0, 0,
        fmt::format("cannot create the output file: expected a folder at '{}', "
                    "found {}",
                    folder.string(), std::filesystem::exists(folder, ec) ? "a file" : "nothing"));
  }
}

AtomicOutput::AtomicOutput(const std::filesystem::path& path, const std::filesystem::path& protect)
    : path_(path),
      temporary_(fmt::format("{}.tmp{}", path.string(), static_cast<long>(::getpid()))) {
  CheckOutputPath(path, protect);
}

AtomicOutput::~AtomicOutput() {
  std::error_code ec;
  if (!committed_) std::filesystem::remove(temporary_, ec);
}

void AtomicOutput::Commit() {
  std::error_code ec;
  if (!std::filesystem::exists(temporary_, ec)) {
    throw InputError(path_.string(), "", 0, 0, "the output file was not written");
  }
  std::filesystem::rename(temporary_, path_, ec);
  if (ec) throw InputError(path_.string(), "", 0, 0, "cannot move the output file into place");
  committed_ = true;
}

void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write,
                         const std::filesystem::path& protect) {
  AtomicOutput output(path, protect);
  {
    std::ofstream out(output.temporary(), std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string(), "", 0, 0, "cannot create the output file");
    write(out);
    out.close();
    if (!out) throw InputError(path.string(), "", 0, 0, "error while writing the output file");
  }
  output.Commit();
}

}  // namespace mechanist
