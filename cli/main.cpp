// The mechanist command line. Exit codes: 0 success, 1 the check or analysis found failures,
// 2 bad input or usage, 3 internal error.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "io/assembly_reader.h"
#include "io/info_report.h"
#include "io/input_error.h"
#include "kernel/assembly_check.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

int Validate(const std::string& file) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  std::size_t features = 0;
  for (const mechanist::Part& part : assembly.parts()) features += part.features.size();
  std::cout << file << ": valid (" << assembly.parts().size() << " parts, " << features
            << " features, " << diagnostics.size() << " diagnostics)\n";
  return kExitOk;
}

int Info(const std::string& file) {
  const mechanist::Assembly assembly = mechanist::ReadAssembly(file);
  mechanist::WriteInfo(assembly, std::cout);
  const auto diagnostics = mechanist::CheckAssembly(assembly);
  if (!diagnostics.empty()) std::cout << "diagnostics: " << diagnostics.size() << "\n";
  mechanist::WriteDiagnostics(diagnostics, std::cout);
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "mechanist: reads a mechanical assembly and tells whether it can be assembled "
      "and how it moves"};
  app.set_version_flag("--version", std::string("mechanist ") + MECHANIST_VERSION);
  app.require_subcommand(1);

  std::string file;
  CLI::App* validate =
      app.add_subcommand("validate", "Read everything, print diagnostics; exit 0 if valid");
  validate->add_option("FILE", file, "assembly file (.json)")->required();
  CLI::App* info = app.add_subcommand(
      "info", "Parts, triangle counts, features, bounding boxes, units, drivers");
  info->add_option("FILE", file, "assembly file (.json)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }

  try {
    if (*validate) return Validate(file);
    if (*info) return Info(file);
  } catch (const mechanist::InputError& e) {
    std::cerr << "mechanist: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "mechanist: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}
