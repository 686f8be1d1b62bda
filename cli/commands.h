#pragma once

// One factory per command, each in its own file under commands/.

#include "cli/command.h"

namespace mechanist::cli {

Command ValidateCommand();
Command InfoCommand();
Command AnalyzeCommand();
Command CheckCommand();
Command InterferenceCommand();
Command AssembleCommand();
Command SweepCommand();
Command GapsCommand();
Command DragCommand();
Command FeaturesCommand();
Command AdjustCommand();
Command AnimateCommand();
Command ExportCommand();
Command ViewCommand();

}  // namespace mechanist::cli
