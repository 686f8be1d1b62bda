// libFuzzer harness of the mesh readers: the input is a mesh file of the extension this
// harness is built for (MECHANIST_FUZZ_EXTENSION: stl, obj, ply or off; STL ASCII and binary
// share the one extension, the reader tells them apart).
#include "fuzz/fuzz_input.h"
#include "io/mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = mechanist::fuzz::WriteInput(data, size, "input." MECHANIST_FUZZ_EXTENSION);
  mechanist::fuzz::ExpectOnlyInputErrors([&] { mechanist::ReadMesh(path); });
  return 0;
}
