// Parse times of the STEP files of ../shared/data: mechanist's Part 21 scanner alone, then the
// whole model read through it (Part21WorkLibrary) against Open CASCADE's own parser
// (StepSelect_WorkLibrary, StepFile_Read), the peer it replaces, in the same run. Medians of
// five runs, alternating the two readers.
#include <Interface_InterfaceModel.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_Protocol.hxx>
#include <XSControl_WorkSession.hxx>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "io/occt/part21_records.h"
#include "io/occt/part21_work_library.h"

namespace {

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double Seconds(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
  Message::DefaultMessenger()->ChangePrinters().Clear();
  STEPControl_Reader reader;  // loads the STEP protocol
  const Handle(Interface_Protocol) protocol = reader.WS()->Protocol();
  const Handle(StepSelect_WorkLibrary) theirs = new StepSelect_WorkLibrary;
  const Handle(StepSelect_WorkLibrary) ours = new mechanist::Part21WorkLibrary;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(MECHANIST_SHARED_DATA)) {
    const std::string extension = entry.path().extension().string();
    if (extension == ".step" || extension == ".stp" || extension == ".STEP") {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::printf("%-44s %8s %9s %9s %9s %6s\n", "file", "MB", "scan s", "ours s", "OCCT s", "ratio");
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::vector<double> scan, with_ours, with_theirs;
    for (int run = 0; run < 5; ++run) {
      scan.push_back(Seconds([&] { (void)mechanist::ReadPart21Records(text); }));
      Handle(Interface_InterfaceModel) model;
      with_ours.push_back(Seconds([&] { ours->ReadFile(file.c_str(), model, protocol); }));
      with_theirs.push_back(Seconds([&] { theirs->ReadFile(file.c_str(), model, protocol); }));
    }
    const std::string name = file.parent_path().filename().string();
    std::printf("%-44s %8.2f %9.3f %9.3f %9.3f %6.2f\n", name.substr(0, 44).c_str(),
                text.size() / 1e6, Median(scan), Median(with_ours), Median(with_theirs),
                Median(with_theirs) / Median(with_ours));
  }
}
