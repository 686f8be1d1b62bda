#include "io/atomic_file.h"

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

void WriteFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write,
                         const std::filesystem::path& protect) {
  std::error_code ec;
  if (!protect.empty() && std::filesystem::exists(path, ec) &&
      std::filesystem::equivalent(path, protect, ec)) {
    throw InputError(path.string(), "", 0, 0, "refusing to write over the input file");
  }
  const std::filesystem::path temporary =
      path.string() + ".tmp" + std::to_string(static_cast<long>(::getpid()));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path.string(), "", 0, 0, "cannot create the output file");
    try {
      write(out);
    } catch (...) {
      out.close();
      std::filesystem::remove(temporary, ec);
      throw;
    }
    out.close();
    if (!out) {
      std::filesystem::remove(temporary, ec);
      throw InputError(path.string(), "", 0, 0, "error while writing the output file");
    }
  }
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw InputError(path.string(), "", 0, 0, "cannot move the output file into place");
  }
}

}  // namespace mechanist
