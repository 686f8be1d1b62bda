#include <fmt/format.h>
#include <sys/time.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/command.h"
#include "io/input_error.h"
#include "io/load_assembly.h"
#include "kernel/support/number_format.h"
#include "reasoning/adjustment.h"

namespace mechanist::cli {

double g_read_timeout = 300;

namespace {

// The message the alarm writes, prepared beforehand: a signal handler may only write and exit.
std::string g_timeout_message;
// Whether a progress line on stderr waits for its end (ReadingProgress), so that the message
// starts a line of its own.
volatile std::sig_atomic_t g_progress_line_open = 0;

void OnReadTimeout(int) {
  // No exception can leave Open CASCADE at an arbitrary point safely (it may hold the heap's
  // lock): the process ends here, before any output file is written.
  if (g_progress_line_open) {
    [[maybe_unused]] const auto ended = ::write(STDERR_FILENO, "\n", 1);
  }
  [[maybe_unused]] const auto written =
      ::write(STDERR_FILENO, g_timeout_message.data(), g_timeout_message.size());
  ::_exit(kExitUsage);
}

// While alive, an alarm ends the process with exit code 2 and a message naming `file` when
// reading takes longer than g_read_timeout: a damaged file can send Open CASCADE's reader
// into an endless loop.
class ReadTimeout {
 public:
  explicit ReadTimeout(const std::string& file) {
    if (!(g_read_timeout > 0)) return;
    g_timeout_message = fmt::format(
        "mechanist: error: {}: reading it took longer than {} s (--read-timeout); the file may be "
        "damaged\n",
        file, FormatNumber(g_read_timeout));
    std::signal(SIGALRM, OnReadTimeout);
    itimerval timer{};
    timer.it_value.tv_sec = static_cast<time_t>(g_read_timeout);
    timer.it_value.tv_usec =
        static_cast<suseconds_t>(1e6 * (g_read_timeout - std::floor(g_read_timeout)));
    ::setitimer(ITIMER_REAL, &timer, nullptr);
    armed_ = true;
  }
  ~ReadTimeout() {
    if (!armed_) return;
    const itimerval off{};
    ::setitimer(ITIMER_REAL, &off, nullptr);
    std::signal(SIGALRM, SIG_DFL);
  }
  ReadTimeout(const ReadTimeout&) = delete;
  ReadTimeout& operator=(const ReadTimeout&) = delete;

 private:
  bool armed_ = false;
};

// Shows the reading of each STEP file on stderr when it is a terminal, a line per file
// ("reading motor.step:  42%"); ends the line of a reading that failed when it goes (and says
// it is open to the read-timeout alarm), so that the error starts a line of its own.
class ReadingProgress {
 public:
  ReadingProgress() = default;
  ~ReadingProgress() {
    if (unfinished_) std::fputc('\n', stderr);
    g_progress_line_open = 0;
  }
  ReadingProgress(const ReadingProgress&) = delete;
  ReadingProgress& operator=(const ReadingProgress&) = delete;

  // What LoadOptions::reading takes; empty when stderr is not a terminal.
  StepFileProgress Lines() {
    if (!::isatty(STDERR_FILENO)) return {};
    return [this](const std::filesystem::path& file, double fraction) {
      const int percent = static_cast<int>(100 * fraction);
      if (file == file_ && percent == percent_) return;
      file_ = file;
      percent_ = percent;
      unfinished_ = percent < 100;
      std::fprintf(stderr, "\rreading %s: %3d%%%s", file.filename().c_str(), percent,
                   unfinished_ ? "" : "\n");
      g_progress_line_open = unfinished_;
    };
  }

 private:
  std::filesystem::path file_;
  int percent_ = -1;
  bool unfinished_ = false;
};

}  // namespace

void Session::Report(const std::string& path, std::string content) {
  if (!path.empty()) reports.emplace_back(path, std::move(content));
}

void WithinReadTimeout(const std::string& file, const std::function<void()>& read) {
  const ReadTimeout timeout(file);
  read();
}

Assembly ReadInput(const std::string& file) {
  const ReadTimeout timeout(file);
  ReadingProgress progress;
  return LoadAssembly(file, {.reading = progress.Lines()});
}

Assembly LoadAdjusted(const std::string& file, std::ostream& out) {
  AdjustmentSummary summary;
  const ReadTimeout timeout(file);
  ReadingProgress progress;
  Assembly assembly =
      LoadAssembly(file, {.adjust = true, .adjustments = &summary, .reading = progress.Lines()});
  for (std::size_t k = 0; k < summary.adjustments.size(); ++k) {
    const Adjustment& a = assembly.adjustments()[k];
    if (!summary.adjustments[k].used) continue;
    const bool rotate = a.kind == Adjustment::Kind::kRotate;
    const double value = summary.adjustments[k].value /
                         (rotate ? assembly.units().rad_per_angle : assembly.units().mm_per_length);
    out << "adjusted: " << a.id << " = " << FormatNumber(std::round(value * 1e6) / 1e6 + 0.0, 9)
        << " " << (rotate ? assembly.units().angle : assembly.units().length);
    const auto& loosened = summary.adjustments[k].loosened;
    for (std::size_t f = 0; f < loosened.size(); ++f) {
      out << (f ? ", " : ", locked; tightened: ") << assembly.FeatureName(loosened[f]);
    }
    out << "\n";
  }
  if (!summary.all_met) out << "adjusted: some goals are not met (mechanist adjust tells)\n";
  return assembly;
}

std::optional<std::size_t> DriverIndex(const std::string& file, const Assembly& assembly,
                                       const std::string& driver) {
  if (driver.empty()) return std::nullopt;
  for (std::size_t d = 0; d < assembly.drivers().size(); ++d) {
    if (assembly.drivers()[d].id == driver) return d;
  }
  throw InputError(file, "", 0, 0,
                   fmt::format("--driver: expected a driver id, found \"{}\"", driver));
}

std::function<void(double)> Progress(const char* what) {
  if (!::isatty(STDERR_FILENO)) return {};
  return [what, last = -1](double fraction) mutable {
    const int percent = static_cast<int>(100 * fraction);
    if (percent == last) return;
    last = percent;
    std::fprintf(stderr, "\r%s: %3d%%%s", what, percent, percent == 100 ? "\n" : "");
  };
}

}  // namespace mechanist::cli
