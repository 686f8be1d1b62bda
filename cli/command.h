#pragma once

// The command table of the mechanist command line: each command (one file in commands/)
// declares its options, what it needs (the file as written or adjusted, the analysis, the
// collision model), and how it runs; main provides what it needs, runs it, writes its reports
// and turns errors into exit codes (0 success, 1 the check or analysis found failures, 2 bad
// input or usage, 3 internal error).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/collision/collision_model.h"
#include "reasoning/analysis.h"

namespace mechanist::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailures = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInternal = 3;

/// How a command gets its assembly.
enum class Input {
  kNone,      ///< it reads its input itself (features: a mesh, an assembly or a STEP file)
  kRead,      ///< the file as written
  kAdjusted,  ///< with its adjustments solved and locked, a line per adjustment on stdout
};

/// What main hands a running command, in the order the command's needs say.
struct Session {
  std::string file;
  std::optional<Assembly> assembly;
  std::optional<Analysis> analysis;
  std::optional<CollisionModel> collision;
  /// Reports to write once the command has run, each atomically and never over the input.
  std::vector<std::pair<std::filesystem::path, std::string>> reports;

  /// Queues a report when `path` is not empty.
  void Report(const std::string& path, std::string content);
};

/// A bound on a number option's value.
enum class Bound { kNone, kNonNegative, kPositive };

/// One option of a command, declared as data: main.cpp alone hands the options to CLI11, whose
/// header takes 8 to 9 seconds to compile in every source that includes it. Read as CLI11
/// reads: `Option("--out", &out, "output folder").Required()`.
struct Option {
  /// Where the parsed value goes; a bool makes a flag.
  using Target =
      std::variant<std::string*, std::size_t*, double*, std::vector<std::string>*, bool*>;

  Option(std::string name, Target target, std::string help)
      : name(std::move(name)), target(target), help(std::move(help)) {}
  Option&& Required() && {
    required = true;
    return std::move(*this);
  }
  Option&& Bounded(Bound b) && {
    bound = b;
    return std::move(*this);
  }
  /// Splits a list's value ("png,glb").
  Option&& Delimiter(char d) && {
    delimiter = d;
    return std::move(*this);
  }
  /// A file the command writes into an existing folder: main checks, before anything is read,
  /// that the folder exists and that the file is not the input (CheckOutputPath). (Outputs
  /// whose folders the command creates, animate's and export's, are not marked.)
  Option&& Output() && {
    output = true;
    return std::move(*this);
  }
  /// May not be given with `other`, an option declared before this one.
  Option&& Excludes(std::string other) && {
    excludes = std::move(other);
    return std::move(*this);
  }

  std::string name;  ///< as given, "--json"
  Target target;
  std::string help;
  bool required = false;
  Bound bound = Bound::kNone;
  char delimiter = '\0';
  std::string excludes;
  bool output = false;
};

/// One command of the table.
struct Command {
  std::string name;
  std::string help;
  std::string file_help = "assembly file (.json or STEP)";
  Input input = Input::kRead;
  bool analysis = false;   ///< Analyze the assembly
  bool collision = false;  ///< build the collision model
  /// The command's own options, in the order `--help` lists them (FILE is declared by main).
  std::vector<Option> options;
  /// Checks the options before anything is read; may be empty.
  std::function<void(const std::string& file)> check;
  /// Runs the command; returns its exit code.
  std::function<int(Session&)> run;
};

/// Every command, in the order `--help` lists them.
std::vector<Command> Commands();

/// How long reading one input may take, seconds (--read-timeout); 0: no bound.
extern double g_read_timeout;

/// The assembly in `file`, read within g_read_timeout; the reading of its STEP files shown on
/// stderr when it is a terminal.
Assembly ReadInput(const std::string& file);
/// Runs `read` within g_read_timeout, naming `file` when it takes longer.
void WithinReadTimeout(const std::string& file, const std::function<void()>& read);
/// The file's assembly with its adjustments solved and locked (the designer tightens the
/// bolts), a line per adjustment on `out`; read as ReadInput reads.
Assembly LoadAdjusted(const std::string& file, std::ostream& out);
/// The index of the driver named by --driver, or nothing for an empty name. Throws InputError.
std::optional<std::size_t> DriverIndex(const std::string& file, const Assembly& assembly,
                                       const std::string& driver);
/// Reports a fraction done on stderr when it is a terminal; empty otherwise.
std::function<void(double)> Progress(const char* what);

}  // namespace mechanist::cli
