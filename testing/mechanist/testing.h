#pragma once

// Mechanism tests for GoogleTest users: load an assembly file or build one in code, then
// assert what the engine concludes, with failure messages in the words of `mechanist check`:
//
//   const auto m = mechanist::testing::Mechanism::Load("hand.json");
//   EXPECT_TRUE(HasRatio(m, "worm_wheel/teeth", "-1/40"));
//   EXPECT_TRUE(HasMobility(m, 1));

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/pair_type.h"
#include "reasoning/analysis.h"

namespace mechanist::testing {

/// An assembly and what the engine concludes about it (pairs, subassemblies, motion).
class Mechanism {
 public:
  /// Analyses `assembly`.
  explicit Mechanism(Assembly assembly);
  /// Reads and analyses a file, its adjustments solved and locked when it declares goals
  /// (Adjusted); throws InputError for bad input, like `mechanist check`.
  static Mechanism Load(const std::filesystem::path& file);

  const Assembly& assembly() const { return assembly_; }
  const Analysis& analysis() const { return analysis_; }

 private:
  Assembly assembly_;
  Analysis analysis_;
};

/// The rate of `feature` ("part/feature") about its axis (a turning part) or along it, per
/// unit driver rate, equals `ratio`: "p/q" or an integer exactly, a decimal within 1e-9
/// relative (spec, "Expectations").
::testing::AssertionResult HasRatio(const Mechanism& m, const std::string& feature,
                                    const std::string& ratio);
/// Features `a` and `b` ("part/feature", either order) form a pair, of `type` when given.
::testing::AssertionResult HasPair(const Mechanism& m, const std::string& a, const std::string& b,
                                   std::optional<PairType> type = std::nullopt);
/// The mechanism has `dof` independent freedoms with the drivers released.
::testing::AssertionResult HasMobility(const Mechanism& m, int dof);
/// All `parts` are in one subassembly.
::testing::AssertionResult InSameSubassembly(const Mechanism& m,
                                             const std::vector<std::string>& parts);
/// Some driver moves `part` (`moves` true) or none does (false).
::testing::AssertionResult Moves(const Mechanism& m, const std::string& part, bool moves = true);
/// The assembly can be put together (`assemblable` true: no clash, every step of the file or
/// of the searched sequence clear), or cannot (false). Runs the assembly plan, which sweeps
/// every part: slower than the other checks.
::testing::AssertionResult IsAssemblable(const Mechanism& m, bool assemblable = true);
/// A diagnostic whose code is `text` or whose message contains it, about all `parts`.
::testing::AssertionResult HasDiagnostic(const Mechanism& m, const std::string& text,
                                         const std::vector<std::string>& parts = {});

}  // namespace mechanist::testing
