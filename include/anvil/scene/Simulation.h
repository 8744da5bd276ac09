// Runs a checked case: builds the body, solves the increment, writes the
// outputs (DESIGN §7): VTK series, loads.csv, summary.json, anvil.log.
#pragma once
#include "anvil/scene/Case.h"

#include <string>

namespace anvil::scene {

struct RunOptions {
  std::string output_directory; ///< overrides the case's when not empty
  bool resume = false;          ///< continue from <output directory>/checkpoint.h5
};

/// Returns normally on success; throws InputError for bad input (before any
/// result file is written) and RunError when the solve fails.
void run(const Case& c, const RunOptions& options);

/// The folder a run of `c` writes to.
std::string output_directory(const Case& c, const RunOptions& options);

} // namespace anvil::scene
