// What the libFuzzer harnesses share: the readers take files, so each input is written to a
// file of this process's own, and any exception other than bad input (InputError, which the
// command line answers with exit code 2) is a finding: the command line would exit with 3.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.h"

namespace mechanist::fuzz {

/// A folder of this process's own under the system's temporary folder, created on first use
/// and removed when the process exits normally (a crash or a time-out leaves it behind).
inline const std::filesystem::path& Folder() {
  struct Owned {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("mechanist-fuzz-" + std::to_string(::getpid()));
    Owned() { std::filesystem::create_directories(path); }
    ~Owned() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  };
  static const Owned folder;
  return folder.path;
}

/// Writes `size` bytes at `data` to Folder()/name and returns its path.
inline std::filesystem::path WriteInput(const std::uint8_t* data, std::size_t size,
                                        const std::string& name) {
  const std::filesystem::path path = Folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

/// Runs `body`: bad input is an expected outcome; any other exception aborts, so that
/// libFuzzer keeps the input as a crash.
template <class Body>
void ExpectOnlyInputErrors(Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not an input error (the command line would exit with 3): %s\n", e.what());
    std::abort();
  }
}

}  // namespace mechanist::fuzz
