#include "cli/commands.h"

namespace mechanist::cli {

std::vector<Command> Commands() {
  return {ValidateCommand(),     InfoCommand(),     AnalyzeCommand(), CheckCommand(),
          InterferenceCommand(), AssembleCommand(), SweepCommand(),   GapsCommand(),
          DragCommand(),         FeaturesCommand(), AdjustCommand(),  AnimateCommand(),
          ExportCommand(),       ViewCommand()};
}

}  // namespace mechanist::cli
