// Runs the mechanist executable as a user would and checks exit codes and output.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "run_command.h"

namespace {

using mechanist::testing::CommandResult;

CommandResult Mechanist(const std::string& args) {
  return mechanist::testing::RunCommand(std::string(MECHANIST_EXE) + " " + args);
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

// On a terminal (script(1) gives the command one), reading a STEP file shows its progress on a
// line that ends at 100%; a reading that fails ends its line before the error; through a pipe,
// nothing is shown. Planning an assembly sequence shows its progress too.
TEST(Cli, LongWorkShowsItsProgressOnATerminal) {
  if (std::system("command -v script > /dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
  const std::string as1 = std::string(MECHANIST_SHARED_DATA) + "/step/as1_pe_203.stp";
  const CommandResult piped = Mechanist("info " + as1);
  EXPECT_EQ(piped.exit_code, 0) << piped.out;
  EXPECT_EQ(piped.out.find("reading"), std::string::npos) << piped.out;
  const auto on_terminal = [](const std::string& args) {
    return mechanist::testing::RunCommand("script -qec '" + std::string(MECHANIST_EXE) + " " +
                                          args + "' /dev/null < /dev/null");
  };
  // The terminal turns each line's end into "\r\n".
  const CommandResult shown = on_terminal("info " + as1);
  EXPECT_EQ(shown.exit_code, 0) << shown.out;
  EXPECT_NE(shown.out.find("\rreading as1_pe_203.stp: 100%\r\n"), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("reading as1_pe_203.stp:  12%"), std::string::npos) << shown.out;
  const CommandResult failed = on_terminal("info " + std::string(MECHANIST_SOURCE_DIR) +
                                           "/tests/data/bad/step_no_solid.step");
  EXPECT_EQ(failed.exit_code, 2) << failed.out;
  EXPECT_NE(failed.out.find("%\r\nmechanist: error: "), std::string::npos) << failed.out;
  // Cut short by the read timeout, the error starts a line of its own too (after the progress
  // line when the reading got that far).
  const CommandResult timed_out =
      on_terminal("--read-timeout 0.6 info \"" + std::string(MECHANIST_SHARED_DATA) +
                  "/real/robot_hand_finger_hinges_onshape/Assembly 1.step\"");
  EXPECT_EQ(timed_out.exit_code, 2) << timed_out.out;
  const std::size_t error = timed_out.out.find("mechanist: error: ");
  ASSERT_NE(error, std::string::npos) << timed_out.out;
  EXPECT_TRUE(error == 0 || timed_out.out[error - 1] == '\n') << timed_out.out;
  // So does the planning of an assembly sequence (here the file's steps, checked in turn).
  const CommandResult planned = on_terminal("assemble " + Example("bracket_plate_bolt_nut"));
  EXPECT_NE(planned.out.find("\rassembly sequence:   0%"), std::string::npos) << planned.out;
  EXPECT_NE(planned.out.find("\rassembly sequence: 100%\r\n"), std::string::npos) << planned.out;
  EXPECT_EQ(
      Mechanist("assemble " + Example("bracket_plate_bolt_nut")).out.find("assembly sequence:"),
      std::string::npos);
}

TEST(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(Mechanist("").exit_code, 2);
  EXPECT_EQ(Mechanist("validate").exit_code, 2);
  // A misspelt command is named, with the commands there are.
  const CommandResult misspelt = Mechanist("--read-timeout 5 analyse x.step");
  EXPECT_EQ(misspelt.exit_code, 2);
  EXPECT_NE(misspelt.out.find("unknown command 'analyse'; the commands are: validate, info, "
                              "analyze,"),
            std::string::npos)
      << misspelt.out;
  // A bound says what it expects, not the whole range of a double.
  const CommandResult negative = Mechanist("--read-timeout -1 analyze x.step");
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_NE(negative.out.find("--read-timeout: expected a number of 0 or more, found '-1'"),
            std::string::npos)
      << negative.out;
  EXPECT_NE(Mechanist("--help").out.find("Exit codes: 0 done; 1 "), std::string::npos);
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

TEST(Cli, InfoGivesATurnedPartsBoxFromItsMesh) {
  // The SolidWorks pair's 40-tooth gear (module 2, tip radius 42 mm) is turned in the file:
  // its box is its mesh's extent, not its part-frame box turned (59 mm from its axis).
  const CommandResult info = Mechanist("info \"" + std::string(MECHANIST_SHARED_DATA) +
                                       "/real/spur_pair_20T_40T_solidworks/ISO standard Spur Gear "
                                       "Drive (2-1 ratio).STEP\"");
  ASSERT_EQ(info.exit_code, 0) << info.out;
  const std::regex box(
      R"(2M_40T[^\n]*box \(([-0-9.e]+), ([-0-9.e]+), [-0-9.e]+\) \.\. \(([-0-9.e]+), ([-0-9.e]+), )");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(info.out, m, box)) << info.out;
  for (int i = 1; i <= 4; ++i) {
    EXPECT_GT(std::abs(std::stod(m[i].str())), 41.5) << m[0];
    EXPECT_LT(std::abs(std::stod(m[i].str())), 42.01) << m[0];
  }
}

TEST(Cli, InfoSaysWhichLengthUnitAStepFileDeclares) {
  // The Solid Edge export declares metres (0.12 for 120 mm); its values are read in mm.
  const std::string step =
      std::string(MECHANIST_SHARED_DATA) + "/real/revolute_pin_solidedge_chrono/assembly.stp";
  const CommandResult alone = Mechanist("info " + step);
  ASSERT_EQ(alone.exit_code, 0) << alone.out;
  EXPECT_NE(alone.out.find("units in file: length metre (read in mm; reported: mm, degrees)"),
            std::string::npos)
      << alone.out;
  // Imported by an assembly file in inches: the file's units, then the STEP file's.
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "mechanist_cli_step_units.json";
  std::ofstream(file) << R"({"mechanist": 1, "units": {"length": "in"}, "import": ")" << step
                      << "\"}";
  const CommandResult imported = Mechanist("info " + file.string());
  std::filesystem::remove(file);
  ASSERT_EQ(imported.exit_code, 0) << imported.out;
  EXPECT_NE(imported.out.find("units in file: length in, angle deg"), std::string::npos)
      << imported.out;
  EXPECT_NE(imported.out.find("  STEP file " + step + ": length metre (read in mm)"),
            std::string::npos)
      << imported.out;
}

TEST(Cli, GapsSaysWhenThinGapsMayBePiecesOfOne) {
  // The Solid Edge pin's countersunk bore leaves a 1 mm thick ring beside the arm's collar:
  // at a 1 mm voxel the grid cuts it into pieces, at 0.5 mm it is one gap.
  const std::string step =
      std::string(MECHANIST_SHARED_DATA) + "/real/revolute_pin_solidedge_chrono/assembly.stp";
  const CommandResult coarse = Mechanist("gaps " + step + " --voxel 1");
  ASSERT_EQ(coarse.exit_code, 0) << coarse.out;
  const std::regex note(
      R"(note: ([0-9]+) gaps 1 to 2 voxels thick enclosed by Assem1.body1, Assem1.body2: one )"
      R"(narrow space may be cut into pieces where it is thinner than a voxel; --voxel 0.5 tells)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(coarse.out, m, note)) << coarse.out;
  EXPECT_GE(std::stoi(m[1].str()), 2);
  const CommandResult fine = Mechanist("gaps " + step + " --voxel 0.5");
  ASSERT_EQ(fine.exit_code, 0) << fine.out;
  EXPECT_NE(fine.out.find("gaps: 1 enclosed gap at voxel 0.5 mm"), std::string::npos) << fine.out;
  EXPECT_EQ(fine.out.find("note:"), std::string::npos) << fine.out;
}

TEST(Cli, FeaturesOnlyPartsAreAnalysedAndSkippedByTheGeometricCommands) {
  const std::string sketch = Example("planetary_differential_sketch");
  const CommandResult validate = Mechanist("validate " + sketch);
  EXPECT_EQ(validate.exit_code, 0) << validate.out;
  EXPECT_NE(validate.out.find("valid (5 parts"), std::string::npos) << validate.out;
  const CommandResult info = Mechanist("info " + sketch);
  EXPECT_NE(info.out.find("carrier: no mesh (features only)"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("brake: rotation of ring/teeth relative to the ground, 0 rev/s"),
            std::string::npos)
      << info.out;
  const CommandResult check = Mechanist("check " + sketch);
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_NE(check.out.find("8 passed, 0 failed"), std::string::npos) << check.out;
  const std::string skipped =
      "skipped, no geometry (features only): carrier, frame, planet, ring, sun";
  for (const std::string command : {"interference", "assemble", "sweep", "gaps --voxel 1"}) {
    const CommandResult run = Mechanist(command + " " + sketch);
    EXPECT_EQ(run.exit_code, 0) << command << ": " << run.out;
    EXPECT_NE(run.out.find(skipped), std::string::npos) << command << ": " << run.out;
  }
  // features lists what it read from faces, and names the parts without any.
  const CommandResult features = Mechanist("features " + sketch);
  EXPECT_EQ(features.exit_code, 0) << features.out;
  EXPECT_NE(features.out.find(skipped), std::string::npos) << features.out;
  EXPECT_EQ(features.out.find("carrier:"), std::string::npos) << features.out;
  const CommandResult brake = Mechanist("sweep " + sketch + " --driver brake");
  EXPECT_NE(brake.out.find("driver brake is held (rate 0): nothing runs"), std::string::npos)
      << brake.out;
}

TEST(Cli, ReadingThatTakesTooLongEndsWithTwo) {
  // The robot hand export takes seconds to read: a bound of 50 ms stops it, as it stops a
  // damaged file that sends Open CASCADE's reader into an endless loop.
  const std::string hand = std::string(MECHANIST_SHARED_DATA) +
                           "/real/robot_hand_finger_hinges_onshape/Assembly\\ 1.step";
  const CommandResult run = Mechanist("--read-timeout 0.05 analyze " + hand);
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("Assembly 1.step: reading it took longer than 0.05 s (--read-timeout)"),
            std::string::npos)
      << run.out;
  EXPECT_EQ(Mechanist("--read-timeout -1 validate " + hand).exit_code, 2);
}

// A binary STL declaring `triangles` triangles, of the size they take (50 bytes each after an
// 84-byte header), written sparse: the file takes no room on the disk.
std::filesystem::path SparseStl(const std::filesystem::path& file, std::uint32_t triangles) {
  {
    std::ofstream out(file, std::ios::binary);
    char header[84] = {};
    std::memcpy(header + 80, &triangles, sizeof triangles);
    out.write(header, sizeof header);
  }
  std::filesystem::resize_file(file, 84 + 50ull * triangles);
  return file;
}

TEST(Cli, AMeshTooLargeForTheMemoryFailsBeforeItIsReadAndSaysWhatItNeeds) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_memory";
  std::filesystem::create_directories(dir);
  // Four billion triangles: 200 GB of file, and more memory than any machine this runs on has.
  const std::filesystem::path stl = SparseStl(dir / "huge.stl", 4'000'000'000u);
  std::ofstream(dir / "huge.json")
      << R"({"mechanist": 1, "parts": [{"id": "p", "mesh": "huge.stl"}]})";
  for (const std::string& command :
       {"features " + stl.string(),
        "analyze " + (dir / "huge.json").string() + " --json " + (dir / "report.json").string()}) {
    const CommandResult run = Mechanist(command);
    EXPECT_EQ(run.exit_code, 2) << run.out;
    // 200 GB of file, seven bytes of memory for each at most.
    EXPECT_NE(run.out.find("huge.stl: reading it needs about 1400.0 GB of memory (a mesh file); "),
              std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find(" are available"), std::string::npos) << run.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "report.json"));
  EXPECT_EQ(std::filesystem::file_size(stl), 84 + 50ull * 4'000'000'000u);  // untouched
  std::filesystem::remove_all(dir);
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MECHANIST_ASAN 1
#endif
#endif

TEST(Cli, AnAddressSpaceLimitBoundsWhatAFileMayTakeToRead) {
#ifdef MECHANIST_ASAN
  GTEST_SKIP() << "AddressSanitizer's shadow memory does not fit under an address-space limit";
#endif
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_cli_memory_limit";
  std::filesystem::create_directories(dir);
  // 20 million triangles, 1 GB of file: it would fit this machine's memory, not 2 GB of
  // address space (ulimit -v), which the process's libraries share.
  const std::filesystem::path stl = SparseStl(dir / "big.stl", 20'000'000u);
  const CommandResult run = mechanist::testing::RunCommand(
      "ulimit -v 2000000 && " + std::string(MECHANIST_EXE) + " features " + stl.string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  // The limit, not the machine's memory, refused it: what is left is under the 2 GB.
  std::smatch found;
  ASSERT_TRUE(std::regex_search(
      run.out, found,
      std::regex(R"(big\.stl: reading it needs about 7\.0 GB of memory \(a mesh file\); )"
                 R"(([0-9.]+) (MB|GB) are available)")))
      << run.out;
  EXPECT_LT(std::stod(found[1]) * (found[2] == "GB" ? 1000 : 1), 2000) << run.out;
  std::filesystem::remove_all(dir);
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

TEST(Cli, AnalyzeWritesSummaryJsonAndDot) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "mechanist_cli_analyze";
  std::filesystem::create_directories(dir);
  const CommandResult run =
      Mechanist("analyze " + Example("robot_hand_worm") + " --json " +
                (dir / "report.json").string() + " --dot " + (dir / "graph.dot").string());
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("worm_gear: worm/worm + worm_wheel/teeth, ratio -1/40, self-locking"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("S2: motor_shaft setscrew worm worm_sleeve"), std::string::npos)
      << run.out;
  std::ifstream json(dir / "report.json");
  const std::string report((std::istreambuf_iterator<char>(json)),
                           std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("\"type\": \"worm_gear\""), std::string::npos);
  EXPECT_NE(report.find("\"ratio\": \"-1/40\""), std::string::npos);
  EXPECT_NE(report.find("\"subassemblies\""), std::string::npos);
  std::ifstream dot(dir / "graph.dot");
  const std::string graph((std::istreambuf_iterator<char>(dot)), std::istreambuf_iterator<char>());
  EXPECT_NE(graph.find("subgraph cluster_S1"), std::string::npos);
  EXPECT_NE(graph.find("\"worm\" -- \"worm_wheel\" [label=\"worm_gear -1/40\"]"), std::string::npos)
      << graph;
  // No temporary files are left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            2);
  std::filesystem::remove_all(dir);
}

TEST(Cli, AnalyzeNeverWritesOverItsInput) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "mechanist_cli_self.json";
  std::filesystem::copy_file(Example("bracket_plate_bolt_nut"), file,
                             std::filesystem::copy_options::overwrite_existing);
  const auto size = std::filesystem::file_size(file);
  const CommandResult run = Mechanist("analyze " + file.string() + " --json " + file.string());
  EXPECT_EQ(run.exit_code, 2) << run.out;
  EXPECT_NE(run.out.find("refusing to write over the input"), std::string::npos) << run.out;
  EXPECT_EQ(std::filesystem::file_size(file), size);
  // Before any work: no report on stdout when an output has no folder to go to.
  const std::filesystem::path nowhere =
      std::filesystem::temp_directory_path() / "mechanist_no_such_folder" / "o.json";
  const CommandResult lost = Mechanist("analyze " + file.string() + " --json " + nowhere.string());
  EXPECT_EQ(lost.exit_code, 2) << lost.out;
  EXPECT_EQ(lost.out, "mechanist: error: " + nowhere.string() +
                          ": cannot create the output file: expected a folder at '" +
                          nowhere.parent_path().string() + "', found nothing\n");
  std::filesystem::remove(file);
}

TEST(Cli, CheckReportsEachExpectationAndExitsOneOnFailure) {
  const CommandResult all = Mechanist("check " + Example("bracket_plate_bolt_nut"));
  EXPECT_EQ(all.exit_code, 0) << all.out;
  EXPECT_NE(all.out.find("PASS /expect/0: pair bolt_left/thread + nut_left/thread is fixed"),
            std::string::npos)
      << all.out;
  EXPECT_NE(all.out.find("PASS /expect/4: mobility 0 (found 0"), std::string::npos);
  EXPECT_NE(all.out.find("PASS /expect/5: assemblable true (found assemblable (2 insertions"),
            std::string::npos)
      << all.out;
  EXPECT_NE(all.out.find("\n6 passed, 0 failed\n"), std::string::npos);

  // A file whose expectations are all within reach passes, including a near miss.
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "mechanist_cli_check.json";
  std::ofstream(file) << R"({"mechanist": 1, "parts": [
    {"id": "g1", "library": {"kind": "spur_gear", "teeth": 20, "module": 1, "face_width": 5}},
    {"id": "g2", "library": {"kind": "spur_gear", "teeth": 10, "module": 1, "face_width": 5},
     "pose": {"position": [15.4, 0, 0]}},
    {"id": "g3", "library": {"kind": "spur_gear", "teeth": 10, "module": 1, "face_width": 5},
     "pose": {"position": [-15, 0, 0]}}],
    "expect": [{"pair": ["g1/teeth", "g3/teeth"], "type": "gear"},
               {"diagnostic": "gear_center_distance", "parts": ["g1", "g2"]},
               {"diagnostic": "off by 0.4 mm"}]})";
  const CommandResult run = Mechanist("check " + file.string());
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("3 passed, 0 failed"), std::string::npos) << run.out;
  std::ofstream(file) << R"({"mechanist": 1, "parts": [
    {"id": "g1", "library": {"kind": "spur_gear", "teeth": 20, "module": 1, "face_width": 5}}],
    "expect": [{"mobility": 5}]})";
  const CommandResult failing = Mechanist("check " + file.string());
  EXPECT_EQ(failing.exit_code, 1) << failing.out;
  EXPECT_NE(failing.out.find("0 passed, 1 failed"), std::string::npos) << failing.out;
  // No expectations at all: said, not only counted.
  std::ofstream(file) << R"({"mechanist": 1, "parts": [
    {"id": "g1", "library": {"kind": "spur_gear", "teeth": 20, "module": 1, "face_width": 5}}]})";
  const CommandResult none = Mechanist("check " + file.string());
  EXPECT_EQ(none.exit_code, 0) << none.out;
  EXPECT_NE(none.out.find("no expectations: the file has no `expect` entries"), std::string::npos)
      << none.out;
  std::filesystem::remove(file);
}

TEST(Cli, InterferenceAndAssembleOnAnExampleAndOnAClash) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_asm";
  std::filesystem::create_directories(dir);
  const CommandResult clean = Mechanist("interference " + Example("robot_hand_worm") + " --json " +
                                        (dir / "contacts.json").string());
  EXPECT_EQ(clean.exit_code, 0) << clean.out;
  EXPECT_NE(clean.out.find("interference: 0 clashes, 6 designed fits"), std::string::npos)
      << clean.out;
  EXPECT_NE(clean.out.find("worm and worm_wheel: designed_fit"), std::string::npos) << clean.out;
  std::ifstream contacts(dir / "contacts.json");
  const std::string report((std::istreambuf_iterator<char>(contacts)),
                           std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("\"clashes\": 0"), std::string::npos) << report;
  EXPECT_NE(report.find("\"verdict\": \"designed_fit\""), std::string::npos);

  const CommandResult plan = Mechanist("assemble " + Example("bracket_plate_bolt_nut") +
                                       " --json " + (dir / "plan.json").string());
  EXPECT_EQ(plan.exit_code, 0) << plan.out;
  EXPECT_NE(plan.out.find("1. bolt_left (bolt_left/thread) into bracket_left/base_hole1 along "
                          "(0, 0, -1)"),
            std::string::npos)
      << plan.out;
  std::ifstream plan_json(dir / "plan.json");
  const std::string steps((std::istreambuf_iterator<char>(plan_json)),
                          std::istreambuf_iterator<char>());
  for (const char* key :
       {"\"assemblable\": true", "\"part\": \"bolt_left\"", "\"feature\": \"bolt_left/thread\"",
        "\"into\": \"bracket_left/base_hole1\"", "\"clear\": true", "\"blocked_by\": []",
        "\"travel\": "}) {
    EXPECT_NE(steps.find(key), std::string::npos) << key << "\n" << steps;
  }

  // Two plates in the same place: a clash, and no way to assemble them.
  const std::filesystem::path file = dir / "clash.json";
  std::ofstream(file) << R"({"mechanist": 1, "parts": [
    {"id": "a", "ground": true, "library": {"kind": "plate", "length": 10, "width": 10, "thickness": 2}},
    {"id": "b", "library": {"kind": "plate", "length": 10, "width": 10, "thickness": 2},
     "pose": {"position": [3, 0, 1]}}]})";
  const CommandResult clash = Mechanist("interference " + file.string());
  EXPECT_EQ(clash.exit_code, 1) << clash.out;
  EXPECT_NE(clash.out.find("a and b: clash, depth 1 mm"), std::string::npos) << clash.out;
  const CommandResult blocked = Mechanist("assemble " + file.string());
  EXPECT_EQ(blocked.exit_code, 1) << blocked.out;
  EXPECT_NE(blocked.out.find("assemblable: no"), std::string::npos) << blocked.out;
  std::filesystem::remove_all(dir);
}

TEST(Cli, SweepFindsAnArmHittingAPostWhileTurning) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_sweep";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "arm.json";
  // A shaft turning in a base carries an arm along +x; a post stands on +y at 25 mm.
  std::ofstream(file) << R"({"mechanist": 1, "parts": [
    {"id": "base", "ground": true,
     "library": {"kind": "plate", "length": 100, "width": 100, "thickness": 5,
                 "holes": [{"id": "bearing", "at": [0, 0], "diameter": 6.02}]}},
    {"id": "shaft", "library": {"kind": "shaft", "diameter": 6, "length": 30, "retained": true},
     "pose": {"position": [0, 0, -5]}},
    {"id": "arm", "library": {"kind": "plate", "length": 40, "width": 6, "thickness": 4,
                              "holes": [{"id": "hub", "at": [-15, 0], "diameter": 5.9}]},
     "pose": {"position": [15, 0, 10]}},
    {"id": "post", "ground": true,
     "library": {"kind": "shaft", "diameter": 6, "length": 20, "segments": 64},
     "pose": {"position": [0, 25, 5]}}],
    "drivers": [{"id": "motor", "part": "shaft", "feature": "shaft", "amount": 0.5}]})";
  const CommandResult run =
      Mechanist("sweep " + file.string() + " --json " + (dir / "sweep.json").string());
  EXPECT_EQ(run.exit_code, 1) << run.out;
  EXPECT_NE(run.out.find("sweep over 0.5 rev of motor: 1 clashes"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("clash: arm and post meet at 0.21"), std::string::npos) << run.out;
  std::ifstream json(dir / "sweep.json");
  const std::string report((std::istreambuf_iterator<char>(json)),
                           std::istreambuf_iterator<char>());
  EXPECT_NE(report.find("\"parts\": [\n        \"arm\",\n        \"post\""), std::string::npos)
      << report;
  // Stopping short of the post: no clash.
  const CommandResult short_run = Mechanist("sweep " + file.string() + " --amount 0.2");
  EXPECT_EQ(short_run.exit_code, 0) << short_run.out;
  // Driven the other way the arm needs more than half a turn to come round to the post.
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find(R"("amount": 0.5)"), 13, R"("amount": 0.5, "rate": -1)");
  std::ofstream(file) << text;
  const CommandResult reversed = Mechanist("sweep " + file.string());
  EXPECT_EQ(reversed.exit_code, 0) << reversed.out;
  EXPECT_NE(reversed.out.find("0 clashes"), std::string::npos) << reversed.out;
  const CommandResult round = Mechanist("sweep " + file.string() + " --amount 0.8");
  EXPECT_NE(round.out.find("clash: arm and post meet at 0.7"), std::string::npos) << round.out;
  std::filesystem::remove_all(dir);
}

TEST(Cli, DragSaysWhatMovesAndNamesThePartsItMayMean) {
  const std::string file = Example("planetary_gear_set");
  const CommandResult run = Mechanist("drag " + file + " --part planet_1");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("drag planet_1 about planet_1/"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("moves:"), std::string::npos) << run.out;
  // A part id typed in part: the ids that contain it; none: the parts there are.
  const CommandResult part = Mechanist("drag " + file + " --part PLANET");
  EXPECT_EQ(part.exit_code, 2);
  EXPECT_NE(part.out.find("--part: expected a part id, found \"PLANET\"; parts whose id contains "
                          "it: planet_1, planet_2, planet_3"),
            std::string::npos)
      << part.out;
  const CommandResult none = Mechanist("drag " + file + " --part gearbox");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.out.find("found \"gearbox\"; the parts are: "), std::string::npos) << none.out;
  // A rod fixed in a hub that turns in the frame: the rod has no pair of its own with another
  // subassembly, so it turns on the hub's bearing, and the report names the rod.
  const std::filesystem::path rod =
      std::filesystem::temp_directory_path() / "mechanist_cli_drag_rod.json";
  std::ofstream(rod) << R"({"mechanist": 1, "parts": [
    {"id": "frame", "ground": true, "features": [{"id": "bearing", "kind": "hole",
      "origin": [0, 0, -10], "axis": [0, 0, 1], "diameter": 4, "length": 10, "through": true}]},
    {"id": "hub", "features": [
      {"id": "journal", "kind": "shaft", "origin": [0, 0, -10], "axis": [0, 0, 1],
       "diameter": 4, "length": 10, "retained": true},
      {"id": "socket", "kind": "hole", "origin": [5, 0, 0], "axis": [1, 0, 0],
       "diameter": 4, "length": 10, "through": true}]},
    {"id": "rod", "features": [{"id": "spigot", "kind": "shaft", "origin": [5, 0, 0],
      "axis": [1, 0, 0], "diameter": 4, "length": 10}]}],
    "overrides": [{"pair": ["hub/socket", "rod/spigot"], "type": "fixed"}]})";
  const CommandResult turned = Mechanist("drag " + rod.string() + " --part rod");
  std::filesystem::remove(rod);
  EXPECT_EQ(turned.exit_code, 0) << turned.out;
  EXPECT_NE(turned.out.find("drag rod about hub/journal: allowable motion 1 freedom"),
            std::string::npos)
      << turned.out;
  EXPECT_NE(turned.out.find("  rod turns 1 rev about"), std::string::npos) << turned.out;
  const CommandResult feature = Mechanist("drag " + file + " --part planet_1 --feature nothing");
  EXPECT_EQ(feature.exit_code, 2);
  EXPECT_NE(feature.out.find("--feature: expected a feature of part planet_1, found \"nothing\"; "
                             "the features are: "),
            std::string::npos)
      << feature.out;
}

TEST(Cli, GapsReportsTheEnclosedCavityAndWritesItsVolume) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_gaps";
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "gaps.json").string(), vti = (dir / "gaps.vti").string();
  const CommandResult closed = Mechanist("gaps " + Example("sealed_enclosure") +
                                         " --voxel 2 --json " + json + " --vtk " + vti);
  EXPECT_EQ(closed.exit_code, 0) << closed.out;
  EXPECT_NE(closed.out.find("gaps: 1 enclosed gap at voxel 2 mm"), std::string::npos) << closed.out;
  EXPECT_NE(closed.out.find("enclosed by floor, cover, wall_left, wall_right, wall_front, "
                            "wall_back"),
            std::string::npos)
      << closed.out;
  std::ifstream report_in(json);
  const std::string report((std::istreambuf_iterator<char>(report_in)),
                           std::istreambuf_iterator<char>());
  const auto voxels_at = report.find("\"voxels\": ");
  ASSERT_NE(voxels_at, std::string::npos) << report;
  const long long voxels = std::stoll(report.substr(voxels_at + 10));

  // The volume file: its gap cells are the reported gap's voxels.
  std::ifstream vti_in(vti, std::ios::binary);
  const std::string volume((std::istreambuf_iterator<char>(vti_in)),
                           std::istreambuf_iterator<char>());
  // The raw data start after the underscore that follows the AppendedData tag; "state" is the
  // first array (offset 0).
  const auto tag = volume.find("<AppendedData encoding=\"raw\">");
  ASSERT_NE(tag, std::string::npos);
  const auto data = volume.find('_', tag) + 1;
  unsigned long long count = 0;
  std::memcpy(&count, volume.data() + data, sizeof count);
  ASSERT_GT(volume.size(), data + 8 + count);
  long long gap_cells = 0;
  for (unsigned long long i = 0; i < count; ++i) gap_cells += volume[data + 8 + i] == 1;
  EXPECT_EQ(gap_cells, voxels);
  EXPECT_NE(volume.find("Name=\"gap\""), std::string::npos);

  // The same input gives the same report.
  const CommandResult again = Mechanist("gaps " + Example("sealed_enclosure") +
                                        " --voxel 2 --json " + (dir / "again.json").string());
  std::ifstream again_in(dir / "again.json");
  EXPECT_EQ(report, std::string((std::istreambuf_iterator<char>(again_in)),
                                std::istreambuf_iterator<char>()));

  // At 0.5 mm the drain hole opens the cavity.
  const CommandResult open = Mechanist("gaps " + Example("sealed_enclosure") + " --voxel 0.5");
  EXPECT_EQ(open.exit_code, 0) << open.out;
  EXPECT_NE(open.out.find("gaps: 0 enclosed gaps"), std::string::npos) << open.out;

  // Bad voxels and writing over the input.
  const CommandResult negative = Mechanist("gaps " + Example("sealed_enclosure") + " --voxel -1");
  EXPECT_EQ(negative.exit_code, 2) << negative.out;
  EXPECT_NE(negative.out.find("--voxel"), std::string::npos) << negative.out;
  const CommandResult tiny = Mechanist("gaps " + Example("sealed_enclosure") + " --voxel 1e-5");
  EXPECT_EQ(tiny.exit_code, 2) << tiny.out;
  EXPECT_NE(tiny.out.find("voxels along an axis"), std::string::npos) << tiny.out;
  const CommandResult over = Mechanist("gaps " + Example("sealed_enclosure") +
                                       " --voxel 2 --json " + Example("sealed_enclosure"));
  EXPECT_EQ(over.exit_code, 2) << over.out;
  std::filesystem::remove_all(dir);
}

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::size_t FileCount(const std::filesystem::path& dir) {
  std::size_t n = 0;
  if (!std::filesystem::exists(dir)) return 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

// The suite runs under xvfb-run (scripts/test.sh), so the renders have a display.
TEST(Cli, AnimateWritesFramesVideosSeriesAndGltf) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_anim";
  std::filesystem::remove_all(dir);
  const CommandResult run = Mechanist("animate " + Example("robot_hand_worm") + " --out " +
                                      dir.string() + " --frames 4 --size 160x120 --view top");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("animation: 4 frames, driver motor over 1"), std::string::npos) << run.out;
  for (const char* name : {"frame_0000.png", "frame_0003.png", "motion.ogv", "motion.mp4",
                           "motion.pvd", "motion/frame_0003.vtp", "motion.glb"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0004.png"));
  EXPECT_EQ(FileCount(dir), 4u + 2u + 1u + 4u + 1u);  // no temporary file is left
  EXPECT_EQ(Slurp(dir / "frame_0000.png").substr(1, 3), "PNG");
  // The same input gives byte-identical series and glTF.
  const std::string glb = Slurp(dir / "motion.glb"), pvd = Slurp(dir / "motion/frame_0002.vtp");
  const CommandResult again = Mechanist("animate " + Example("robot_hand_worm") + " --out " +
                                        dir.string() + " --frames 4 --format glb,pvd");
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_EQ(Slurp(dir / "motion.glb"), glb);
  EXPECT_EQ(Slurp(dir / "motion/frame_0002.vtp"), pvd);
  std::filesystem::remove_all(dir);
}

TEST(Cli, AnimateWithoutADisplayWritesTheFilesThatNeedNone) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_nodisp";
  std::filesystem::remove_all(dir);
  const std::string animate = "animate " + Example("planetary_gear_set") + " --out " + dir.string();
  const CommandResult png = Mechanist("--version > /dev/null; env -u DISPLAY " +
                                      std::string(MECHANIST_EXE) + " " + animate + " --frames 3");
  EXPECT_EQ(png.exit_code, 2) << png.out;
  EXPECT_NE(png.out.find("no display"), std::string::npos) << png.out;
  EXPECT_NE(png.out.find("xvfb-run"), std::string::npos) << png.out;
  EXPECT_EQ(FileCount(dir), 0u);
  const CommandResult files =
      Mechanist("--version > /dev/null; env -u DISPLAY " + std::string(MECHANIST_EXE) + " " +
                animate + " --frames 3 --format pvd,glb");
  EXPECT_EQ(files.exit_code, 0) << files.out;
  EXPECT_EQ(FileCount(dir), 1u + 3u + 1u);
  std::filesystem::remove_all(dir);
}

TEST(Cli, AnimateRejectsBadOptionsAndShowsGaps) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_anim2";
  std::filesystem::remove_all(dir);
  const std::string animate = "animate " + Example("sealed_enclosure") + " --out " + dir.string();
  for (const auto& [option, named] :
       {std::pair<std::string, std::string>{"--size 12x9000", "--size"},
        {"--size wide", "--size"},
        {"--format png,gif", "--format"},
        {"--view diagonal", "--view"},
        {"--frames 0", "--frames"},
        {"--fps 0", "--fps"},
        {"--gaps 1e-6", "--gaps"},
        {"--driver nobody", "--driver"}}) {
    const CommandResult bad = Mechanist(animate + " " + option);
    EXPECT_EQ(bad.exit_code, 2) << option << ": " << bad.out;
    EXPECT_NE(bad.out.find(named), std::string::npos) << option << ": " << bad.out;
  }
  EXPECT_EQ(FileCount(dir), 0u);
  // Without ffmpeg on the PATH an MP4 is refused before anything is written.
  const std::filesystem::path empty = dir.string() + "_path";
  std::filesystem::create_directories(empty);
  const CommandResult mp4 = Mechanist("--version > /dev/null; PATH=" + empty.string() + " " +
                                      std::string(MECHANIST_EXE) + " " + animate + " --format mp4");
  EXPECT_EQ(mp4.exit_code, 2) << mp4.out;
  EXPECT_NE(mp4.out.find("ffmpeg"), std::string::npos) << mp4.out;
  EXPECT_EQ(FileCount(dir), 0u);
  std::filesystem::remove_all(empty);
  // Nothing drives the box; its gap is drawn and written.
  const CommandResult gaps =
      Mechanist(animate + " --frames 2 --gaps 2 --format png,pvd,glb --size 200x150");
  EXPECT_EQ(gaps.exit_code, 0) << gaps.out;
  EXPECT_NE(gaps.out.find("nothing moves: no driver"), std::string::npos) << gaps.out;
  EXPECT_NE(gaps.out.find("gaps: 1 at voxel 2 mm"), std::string::npos) << gaps.out;
  EXPECT_TRUE(std::filesystem::exists(dir / "motion" / "gaps.vtp"));
  EXPECT_NE(Slurp(dir / "motion.glb").find("\"name\":\"gaps\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Cli, AdjustSolvesTheSwingAndWritesTheAdjustedFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_adj";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string swung = Example("robot_hand_worm_adjust");
  const CommandResult run = Mechanist("adjust " + swung + " --json " + (dir / "r.json").string() +
                                      " --write " + (dir / "adjusted.json").string());
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("motor_swing: rotate motor_body about housing/motor_hole_a by -3.0000 "
                         "deg"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("goal mesh worm/worm with worm_wheel/teeth: met"), std::string::npos)
      << run.out;
  EXPECT_NE(Slurp(dir / "r.json").find("\"value\": -3.0"), std::string::npos);
  // The written file stands on its own: its poses are the adjusted ones, so check passes.
  const CommandResult written = Mechanist("check " + (dir / "adjusted.json").string());
  EXPECT_EQ(written.exit_code, 0) << written.out;
  EXPECT_NE(written.out.find("9 passed, 0 failed"), std::string::npos) << written.out;
  // Every command sees the adjusted assembly and says so.
  const CommandResult analyze = Mechanist("analyze " + swung);
  EXPECT_NE(analyze.out.find("adjusted: motor_swing = -3 deg"), std::string::npos) << analyze.out;
  EXPECT_NE(analyze.out.find("worm_gear"), std::string::npos) << analyze.out;
  // Never over the input; a file without adjustments is a usage error.
  EXPECT_EQ(Mechanist("adjust " + swung + " --write " + swung).exit_code, 2);
  const CommandResult none = Mechanist("adjust " + Example("robot_hand_worm"));
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_NE(none.out.find("/adjustments"), std::string::npos) << none.out;
  // A range too narrow: the goal is missed and the bound named; exit 1.
  std::string text = Slurp(swung);
  text.replace(text.find("\"range\": [-10, 10]"), 18, "\"range\": [-2, 10]");
  {
    std::ofstream out(dir / "narrow.json");
    out << text;
  }
  const CommandResult narrow = Mechanist("adjust " + (dir / "narrow.json").string());
  EXPECT_EQ(narrow.exit_code, 1) << narrow.out;
  EXPECT_NE(narrow.out.find("NOT met"), std::string::npos) << narrow.out;
  EXPECT_NE(narrow.out.find("at its lower bound"), std::string::npos) << narrow.out;
  std::filesystem::remove_all(dir);
}

TEST(Cli, FeaturesRecognisesGearsInMeshesAndAssemblies) {
  const std::string gear =
      std::string(MECHANIST_SHARED_DATA) + "/gears/spur_pair/spur_pair_gear_A_z17_m1.stl";
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mechanist_cli_feat";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const CommandResult one = Mechanist("features " + gear + " --json " + (dir / "f.json").string());
  EXPECT_EQ(one.exit_code, 0) << one.out;
  EXPECT_NE(one.out.find("teeth: gear at (0, 0, -3) axis (0, 0, 1) 17 teeth module 1 mm"),
            std::string::npos)
      << one.out;
  EXPECT_NE(Slurp(dir / "f.json").find("\"teeth\": 17"), std::string::npos);
  // An assembly of the two STL gears alone: analyze finds the gear pair.
  {
    std::ofstream out(dir / "pair.json");
    out << R"({"mechanist": 1, "parts": [{"id": "a", "mesh": ")" << gear << R"("},
      {"id": "b", "mesh": ")"
        << std::string(MECHANIST_SHARED_DATA) + "/gears/spur_pair/spur_pair_gear_B_z31_m1.stl"
        << R"("}]})";
  }
  const CommandResult listed = Mechanist("features " + (dir / "pair.json").string());
  EXPECT_NE(listed.out.find("b: prismatic along (0, 0, 1), 2 features recognised"),
            std::string::npos)
      << listed.out;
  const CommandResult analyze = Mechanist("analyze " + (dir / "pair.json").string());
  EXPECT_NE(analyze.out.find("gear: a/teeth + b/teeth"), std::string::npos) << analyze.out;
  const CommandResult bad = Mechanist("features " + (dir / "missing.stl").string());
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  // A file of no kind it reads: what it reads, all of it.
  const CommandResult text = Mechanist("features " + (dir / "notes.txt").string());
  EXPECT_EQ(text.exit_code, 2) << text.out;
  EXPECT_NE(text.out.find("notes.txt: expected a mesh (.stl, .obj, .ply, .off), an assembly "
                          "(.json) or a STEP file (.step, .stp); found the extension '.txt'"),
            std::string::npos)
      << text.out;
  std::filesystem::remove_all(dir);
}

TEST(Cli, StepAssembliesAreAnalysedWithoutWrittenFeatures) {
  const std::string as1 = std::string(MECHANIST_SHARED_DATA) + "/step/as1_pe_203.stp";
  const CommandResult analyze = Mechanist("analyze " + as1);
  EXPECT_EQ(analyze.exit_code, 0) << analyze.out;
  EXPECT_NE(analyze.out.find("subassemblies: 1\n"), std::string::npos) << analyze.out;
  const CommandResult features = Mechanist("features " + as1);
  EXPECT_EQ(features.exit_code, 0) << features.out;
  EXPECT_NE(features.out.find("AS1_PE_ASM.ROD.ROD: "), std::string::npos) << features.out;
  EXPECT_NE(features.out.find("info nut_on_bolt: part 'AS1_PE_ASM.ROD.NUT_2'"), std::string::npos)
      << features.out;
  // The ground is the analysis' choice, not the features'.
  EXPECT_EQ(features.out.find("ground_chosen"), std::string::npos) << features.out;
  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "mechanist_bad.stp";
  {
    std::ofstream out(bad);
    out << "ISO-10303-21;\nnot a step file\n";
  }
  const CommandResult broken = Mechanist("analyze " + bad.string());
  EXPECT_EQ(broken.exit_code, 2) << broken.out;
  // The STEP file itself is the place: no pointer into the import file made up around it.
  EXPECT_NE(broken.out.find(bad.string() + ": cannot import"), std::string::npos) << broken.out;
  EXPECT_NE(broken.out.find("cannot read it as STEP"), std::string::npos) << broken.out;
  EXPECT_EQ(broken.out.find("/import"), std::string::npos) << broken.out;
  std::filesystem::remove(bad);
}

TEST(Cli, ExportNeedsAnOutputAndAPositiveDensity) {
  const std::string file = Example("robot_hand_worm");
  const CommandResult none = Mechanist("export " + file);
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_NE(none.out.find("expected --urdf or --mjcf"), std::string::npos) << none.out;
  const auto out = std::filesystem::temp_directory_path() / "mechanist_cli_export";
  std::filesystem::remove_all(out);
  const CommandResult density =
      Mechanist("export " + file + " --density -1 --urdf " + (out / "m.urdf").string());
  EXPECT_EQ(density.exit_code, 2) << density.out;
  EXPECT_NE(density.out.find("--density"), std::string::npos) << density.out;
  EXPECT_FALSE(std::filesystem::exists(out / "m.urdf"));
  const CommandResult ok =
      Mechanist("export " + file + " --no-limits --urdf " + (out / "m.urdf").string());
  EXPECT_EQ(ok.exit_code, 0) << ok.out;
  EXPECT_TRUE(std::filesystem::exists(out / "m_meshes" / "worm_wheel.stl"));
  EXPECT_NE(ok.out.find("movable ranges not searched"), std::string::npos) << ok.out;
}

}  // namespace

TEST(Cli, ViewWritesOnePageAndSaysWhere) {
  const auto out = std::filesystem::temp_directory_path() / "mechanist_cli_view.html";
  std::filesystem::remove(out);
  const CommandResult view =
      Mechanist("view " + Example("robot_hand_worm") + " --out " + out.string());
  EXPECT_EQ(view.exit_code, 0) << view.out;
  EXPECT_NE(view.out.find("viewer: " + out.string()), std::string::npos) << view.out;
  std::ifstream in(out);
  const std::string page((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("<title>worm drive of a robot hand</title>"), std::string::npos);
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);  // three.js inlined
  EXPECT_EQ(Mechanist("view " + Example("robot_hand_worm") + " --out " + Example("robot_hand_worm"))
                .exit_code,
            2);  // never over the input
}
