// The bad-input corpus (tests/data/bad): every file is refused with exit code 2 and a message
// that names the file and says what was expected and found, never a crash, a hang or a
// partial report.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "run_command.h"

namespace mechanist {
namespace {

const std::filesystem::path kBad = std::filesystem::path(MECHANIST_SOURCE_DIR) / "tests/data/bad";

struct Case {
  std::string file, command, message;
  int exit = 0;
};

std::vector<Case> Cases() {
  std::ifstream in(kBad / "expected.json");
  const nlohmann::json expected = nlohmann::json::parse(in);
  std::vector<Case> cases;
  for (const auto& [file, e] : expected.items()) {
    cases.push_back({file, e.at("command"), e.at("message"), e.at("exit")});
  }
  return cases;
}

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, IsRefusedWithAClearMessageAndNoReport) {
  const Case& c = GetParam();
  ASSERT_TRUE(std::filesystem::exists(kBad / c.file)) << c.file;
  const std::string exe = MECHANIST_EXE;
  // From the corpus' folder, as a user names a file beside them; bounded, so that a hang
  // fails the test instead of stopping the suite.
  const auto run = testing::RunCommand("cd '" + kBad.string() + "' && timeout 60 '" + exe + "' " +
                                       c.command + " '" + c.file + "'");
  EXPECT_EQ(run.exit_code, c.exit) << run.out;
  EXPECT_NE(run.out.find("mechanist: error: " + c.file), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(c.message), std::string::npos) << run.out;
  // Asked for a report, it writes none.
  const std::filesystem::path report = std::filesystem::temp_directory_path() /
                                       ("mechanist_bad_" + std::to_string(::getpid()) + ".json");
  std::filesystem::remove(report);
  const std::string reporting = c.command == "features" ? "features" : "analyze";
  const auto again =
      testing::RunCommand("cd '" + kBad.string() + "' && timeout 60 '" + exe + "' " + reporting +
                          " '" + c.file + "' --json '" + report.string() + "'");
  EXPECT_EQ(again.exit_code, c.exit) << again.out;
  EXPECT_FALSE(std::filesystem::exists(report)) << "a report was written for " << c.file;
}

std::string Name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.file;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(Cases()), Name);

TEST(BadInputCorpus, HoldsAtLeastSixtyFilesEachWithItsExpectation) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kBad)) {
    const std::string name = entry.path().filename().string();
    if (name == "expected.json" || name == "README.md") continue;
    ++files;
  }
  EXPECT_GE(files, 60u);
  EXPECT_EQ(files, Cases().size()) << "every file needs its line in expected.json";
}

}  // namespace
}  // namespace mechanist
