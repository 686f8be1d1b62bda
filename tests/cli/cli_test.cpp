// Runs the mechanist executable as a user would and checks exit codes and output.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< stdout and stderr together
};

CommandResult Mechanist(const std::string& args) {
  const std::string command = std::string(MECHANIST_EXE) + " " + args + " 2>&1";
  CommandResult run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

std::string Example(const std::string& name) {
  return std::string(MECHANIST_SOURCE_DIR) + "/examples/" + name + "/assembly.json";
}

TEST(Cli, VersionAndHelp) {
  const CommandResult version = Mechanist("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.out.find("mechanist 0."), std::string::npos) << version.out;
  const CommandResult help = Mechanist("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("validate"), std::string::npos);
  EXPECT_NE(help.out.find("info"), std::string::npos);
}

TEST(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(Mechanist("").exit_code, 2);
  EXPECT_EQ(Mechanist("frobnicate").exit_code, 2);
  EXPECT_EQ(Mechanist("validate").exit_code, 2);
}

TEST(Cli, ValidateAndInfoOnTheMainExample) {
  const CommandResult validate = Mechanist("validate " + Example("robot_hand_worm"));
  EXPECT_EQ(validate.exit_code, 0) << validate.out;
  EXPECT_NE(validate.out.find("valid (10 parts"), std::string::npos) << validate.out;
  const CommandResult info = Mechanist("info " + Example("robot_hand_worm"));
  EXPECT_EQ(info.exit_code, 0) << info.out;
  EXPECT_NE(info.out.find("assembly: worm drive of a robot hand"), std::string::npos);
  EXPECT_NE(info.out.find("housing [ground]: library:plate"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("teeth: worm_wheel"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("motor: rotation of motor_shaft/shaft relative to motor_body"),
            std::string::npos)
      << info.out;
  // Deterministic output.
  EXPECT_EQ(Mechanist("info " + Example("robot_hand_worm")).out, info.out);
}

TEST(Cli, BadInputExitsWithTwoAndNamesThePlace) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "mechanist_cli_bad.json";
  std::ofstream(file) << "{\"mechanist\": 1,\n \"parts\": [{\"id\": \"p\", \"library\": "
                         "{\"kind\": \"shaft\", \"diameter\": 0, \"length\": 3}}]}";
  const CommandResult run = Mechanist("validate " + file.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.out.find(file.string() + ":2:"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("/parts/0/library/diameter"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("expected a positive length, found the number 0"), std::string::npos)
      << run.out;
  std::filesystem::remove(file);
  EXPECT_EQ(Mechanist("info /nonexistent/assembly.json").exit_code, 2);
}

}  // namespace
