// Every example under examples/ loads, has a README, and its library meshes are sound.

#include <gtest/gtest.h>

#include <filesystem>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly_check.h"

namespace mechanist {
namespace {

TEST(Examples, EveryExampleLoadsCleanly) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(MECHANIST_SOURCE_DIR) / "examples")) {
    if (!entry.is_directory()) continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_TRUE(std::filesystem::exists(entry.path() / "README.md"));
    const Assembly assembly = LoadAssembly(entry.path() / "assembly.json");
    EXPECT_FALSE(assembly.parts().empty());
    EXPECT_FALSE(assembly.expectations().empty());
    for (const Diagnostic& d : CheckAssembly(assembly)) {
      if (d.severity != Severity::kInfo) ADD_FAILURE() << d.code << ": " << d.message;
    }
    ++count;
  }
  EXPECT_GE(count, 5);
}

}  // namespace
}  // namespace mechanist
