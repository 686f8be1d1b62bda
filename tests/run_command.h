#pragma once

// Test helper: runs a shell command as a user would and keeps what it printed.

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace mechanist::testing {

struct CommandResult {
  int exit_code = -1;  ///< -1 when the command could not run or was killed
  std::string out;     ///< stdout and stderr together
};

/// Runs `command` through the shell with stderr joined to stdout.
inline CommandResult RunCommand(const std::string& command) {
  CommandResult run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace mechanist::testing
