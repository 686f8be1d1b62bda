// libFuzzer harness of the assembly file: the input is an assembly file (JSON with comments),
// loaded as `validate` loads it: read, features recognised, relations read, parts placed,
// fasteners inferred, the ground chosen, adjustments solved. Mesh paths are relative to the
// fuzzing folder, which holds no meshes, so parts are library parts or features only.
#include <string_view>

#include "fuzz/fuzz_input.h"
#include "io/load_assembly.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  mechanist::fuzz::ExpectOnlyInputErrors([&] {
    mechanist::LoadAssemblyText(text, mechanist::fuzz::Folder() / "assembly.json",
                                {.adjust = true});
  });
  return 0;
}
