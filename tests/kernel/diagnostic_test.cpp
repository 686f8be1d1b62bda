#include "kernel/assembly/diagnostic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace mechanist {
namespace {

// Names drawn from few values, so that diagnostics tie on the leading keys and the order is
// decided by the later ones (features, parts, message).
Diagnostic RandomDiagnostic(std::mt19937& random, int serial) {
  const auto name = [&](const char* prefix) { return prefix + std::to_string(random() % 3); };
  Diagnostic d;
  d.code = name("code");
  for (std::size_t k = random() % 3; k > 0; --k) d.features.push_back(name("part/feature"));
  for (std::size_t k = random() % 3; k > 0; --k) d.parts.push_back(name("part"));
  d.message = "finding " + std::to_string(serial);  // unique: the order is total
  return d;
}

std::vector<std::string> Messages(const std::vector<Diagnostic>& diagnostics) {
  std::vector<std::string> messages;
  for (const Diagnostic& d : diagnostics) messages.push_back(d.message);
  return messages;
}

TEST(SortDiagnosticRuns, OrdersLikeOneSortOfTheWhole) {
  // Oracle: std::sort of all the diagnostics. Runs are in order already, reversed or shuffled,
  // of random lengths including empty ones.
  std::mt19937 random(5);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Diagnostic> diagnostics;
    std::vector<std::size_t> run_starts;
    const int runs = 1 + static_cast<int>(random() % 5);
    for (int r = 0; r < runs; ++r) {
      run_starts.push_back(diagnostics.size());
      std::vector<Diagnostic> run;
      for (std::size_t k = random() % 40; k > 0; --k) {
        run.push_back(RandomDiagnostic(random, trial * 1000 + static_cast<int>(run.size()) +
                                                   static_cast<int>(diagnostics.size())));
      }
      switch (random() % 3) {
        case 0:
          std::sort(run.begin(), run.end(), DiagnosticLess);
          break;
        case 1:
          std::sort(run.begin(), run.end(), DiagnosticLess);
          std::reverse(run.begin(), run.end());
          break;
        default:
          break;
      }
      diagnostics.insert(diagnostics.end(), run.begin(), run.end());
    }
    std::vector<Diagnostic> expected = diagnostics;
    std::sort(expected.begin(), expected.end(), DiagnosticLess);
    SortDiagnosticRuns(&diagnostics, run_starts);
    EXPECT_EQ(Messages(diagnostics), Messages(expected)) << "trial " << trial;
  }
}

TEST(SortDiagnosticRuns, RejectsRunsThatDoNotCoverTheDiagnosticsInOrder) {
  std::mt19937 random(1);
  std::vector<Diagnostic> three = {RandomDiagnostic(random, 0), RandomDiagnostic(random, 1),
                                   RandomDiagnostic(random, 2)};
  for (const std::vector<std::size_t>& bad :
       std::vector<std::vector<std::size_t>>{{}, {1}, {0, 2, 1}, {0, 4}}) {
    std::vector<Diagnostic> d = three;
    EXPECT_THROW(SortDiagnosticRuns(&d, bad), std::invalid_argument);
  }
  std::vector<Diagnostic> none;
  EXPECT_NO_THROW(SortDiagnosticRuns(&none, {}));
}

}  // namespace
}  // namespace mechanist
