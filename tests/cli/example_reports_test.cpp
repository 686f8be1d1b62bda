// Pins every example's reports byte for byte (text, JSON, DOT, exit code) against
// tests/cli/golden/, so that restructuring the code cannot change what a user sees.
// scripts/update_golden_reports.sh rewrites them, for an intended change of behaviour only.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"

namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs a command in `dir` as the golden script does: stdout and stderr, then "exit N".
std::string RunIn(const fs::path& dir, const std::string& args) {
  const auto run = mechanist::testing::RunCommand("cd '" + dir.string() + "' && '" +
                                                  std::string(MECHANIST_EXE) + "' " + args);
  return run.out + "exit " + std::to_string(run.exit_code) + "\n";
}

std::vector<std::string> Examples() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(MECHANIST_SOURCE_DIR) / "examples")) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class ExampleReports : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleReports, AreByteIdenticalToThePinnedOnes) {
  const fs::path dir = fs::path(MECHANIST_SOURCE_DIR) / "examples" / GetParam();
  const fs::path golden = fs::path(MECHANIST_SOURCE_DIR) / "tests/cli/golden" / GetParam();
  const fs::path out =
      fs::temp_directory_path() / ("mechanist_reports_" + std::to_string(::getpid())) / GetParam();
  fs::create_directories(out);
  ASSERT_TRUE(fs::exists(golden)) << "no pinned reports: run scripts/update_golden_reports.sh";
  for (const std::string command :
       {"validate", "info", "analyze", "check", "interference", "assemble", "sweep"}) {
    std::vector<std::string> files;
    std::string extra;
    if (command == "analyze") {
      files = {"analyze.json", "analyze.dot"};
      extra =
          " --json '" + (out / files[0]).string() + "' --dot '" + (out / files[1]).string() + "'";
    } else if (command == "interference" || command == "assemble" || command == "sweep") {
      files = {command + ".json"};
      extra = " --json '" + (out / files[0]).string() + "'";
    }
    EXPECT_EQ(RunIn(dir, command + " assembly.json" + extra), Slurp(golden / (command + ".txt")))
        << GetParam() << ": " << command;
    for (const std::string& f : files) {
      EXPECT_EQ(Slurp(out / f), Slurp(golden / f)) << GetParam() << ": " << f;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleReports, ::testing::ValuesIn(Examples()));

}  // namespace
