// libFuzzer harness of STEP import: the input is a STEP file, loaded as `validate` loads a
// STEP file alone (Open CASCADE's reader and tessellation, features of the exact faces, then
// recognition, fasteners and the ground). Open CASCADE's crashes must come back as input
// errors, so its signal handlers are in place while it reads, as in the command line.
#include "fuzz/fuzz_input.h"
#include "io/load_assembly.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = mechanist::fuzz::WriteInput(data, size, "input.step");
  mechanist::fuzz::ExpectOnlyInputErrors([&] { mechanist::LoadAssembly(path); });
  return 0;
}
