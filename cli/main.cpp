// The mechanist command line: the command table (cli/commands.h), one file per command in
// commands/, and here what they share: the options every command has, reading what a command
// needs, writing its reports, and turning errors into exit codes.

#include <fmt/format.h>
#include <fmt/ranges.h>  // fmt::join

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "cli/commands.h"
#include "io/atomic_file.h"
#include "io/input_error.h"
#include "kernel/support/heap_tuning.h"

namespace {

using namespace mechanist::cli;

// A number option's bound, said as a user would (CLI11's own checks print the double's whole
// range: "Value -1 not in range 0.000000 to 17976931348623157...").
CLI::Validator BoundCheck(Bound bound) {
  const bool positive = bound == Bound::kPositive;
  return CLI::Validator(
      [positive](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool number =
            !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
        if (number && (positive ? value > 0 : value >= 0)) return "";
        return fmt::format("expected a number {}, found '{}'",
                           positive ? "above 0" : "of 0 or more", text);
      },
      positive ? "NUMBER > 0" : "NUMBER >= 0");
}

// Declares `option` on `app`; `declared` holds the options declared on `app` before it.
void Declare(const Option& option, CLI::App& app, std::map<std::string, CLI::Option*>& declared) {
  CLI::Option* declaration = std::visit(
      [&](auto* target) {
        if constexpr (std::is_same_v<decltype(target), bool*>) {
          return app.add_flag(option.name, *target, option.help);
        } else {
          return app.add_option(option.name, *target, option.help);
        }
      },
      option.target);
  if (option.required) declaration->required();
  if (option.bound != Bound::kNone) declaration->check(BoundCheck(option.bound));
  if (option.delimiter != '\0') declaration->delimiter(option.delimiter);
  if (!option.excludes.empty()) declaration->excludes(declared.at(option.excludes));
  declared[option.name] = declaration;
}

// Reads what `command` needs, runs it, and writes its reports once it has run.
int Run(const Command& command, const std::string& file) {
  for (const Option& option : command.options) {
    const auto* path = std::get_if<std::string*>(&option.target);
    if (option.output && path && !(*path)->empty()) mechanist::CheckOutputPath(**path, file);
  }
  if (command.check) command.check(file);
  Session session;
  session.file = file;
  if (command.input == Input::kRead) session.assembly = ReadInput(file);
  if (command.input == Input::kAdjusted) session.assembly = LoadAdjusted(file, std::cout);
  if (command.analysis) session.analysis = mechanist::Analyze(*session.assembly);
  if (command.collision) session.collision.emplace(*session.assembly);
  const int code = command.run(session);
  for (const auto& [path, content] : session.reports) {
    mechanist::WriteFileAtomically(path, content, file);
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  mechanist::KeepFreedHeapForReuse();
  CLI::App app{
      "mechanist: reads a mechanical assembly and tells whether it can be assembled "
      "and how it moves"};
  app.set_version_flag("--version", fmt::format("mechanist {}", MECHANIST_VERSION));
  app.require_subcommand(1);
  app.add_option("--read-timeout", g_read_timeout,
                 "seconds reading one input file may take before mechanist gives up with exit "
                 "code 2 (default 300; 0: no bound); before the command")
      ->check(BoundCheck(Bound::kNonNegative));
  app.footer(
      "Exit codes: 0 done; 1 the check or the analysis found failures; 2 bad input or usage; 3 "
      "internal error.");

  std::string file;
  const std::vector<Command> commands = Commands();
  std::vector<CLI::App*> subcommands;
  for (const Command& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.help);
    sub->add_option("FILE", file, command.file_help)->required();
    std::map<std::string, CLI::Option*> declared;
    for (const Option& option : command.options) Declare(option, *sub, declared);
    subcommands.push_back(sub);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // A misspelt command reads as a missing one to CLI11 ("A subcommand is required").
    for (int k = 1; k < argc; ++k) {
      const std::string word = argv[k];
      if (word == "--read-timeout") ++k;  // and its value
      if (word.empty() || word[0] == '-') continue;
      if (std::none_of(commands.begin(), commands.end(),
                       [&](const Command& c) { return c.name == word; })) {
        std::vector<std::string> names;
        for (const Command& c : commands) names.push_back(c.name);
        std::cerr << fmt::format("mechanist: error: unknown command '{}'; the commands are: {}\n",
                                 word, fmt::join(names, ", "));
        return kExitUsage;
      }
      break;
    }
    app.exit(e);
    return kExitUsage;
  }

  try {
    for (std::size_t k = 0; k < commands.size(); ++k) {
      if (*subcommands[k]) return Run(commands[k], file);
    }
  } catch (const mechanist::InputError& e) {
    std::cerr << "mechanist: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    // Past the readers' own estimate (io/internal/memory_budget.h): still the user's to act on.
    std::cerr << "mechanist: error: " << file
              << ": ran out of memory working on it; the input is too large for the memory "
                 "this process may use\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "mechanist: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return kExitUsage;
}
