// Runs a checked case: builds the body, solves the increment, writes the
// outputs (docs/design.md §7): VTK series, loads.csv, summary.json, anvil.log.
#pragma once
#include "anvil/scene/Case.h"
#include "anvil/scene/RunState.h"

#include <string>

namespace anvil::run {

struct RunOptions {
  std::string output_directory; ///< overrides the case's when not empty
  bool resume = false;          ///< continue from <output directory>/checkpoint.h5
  /// With resume: continue although the case, its material cards, meshes or
  /// dies changed since the checkpoint (the log lists the changes).
  bool allow_changes = false;
};

/// How a run that returned ended.
struct RunEnd {
  std::string stop; ///< the stop criterion met, or why the run stopped short
  /// False when time.max_increments ended the run before its stop criterion
  /// (`anvil run` then exits with 4).
  bool complete = true;
  /// SIGINT or SIGTERM when the run stopped for it (core/interrupt), its
  /// last accepted increment written and checkpointed; 0 otherwise.
  int signal = 0;
  bool checkpointed = false; ///< with `signal`: a checkpoint to resume from was written
};

/// Returns when the run ends, its outputs written; throws InputError for bad
/// input (before any result file is written) and RunError when the solve or
/// a write fails. An operation of a chain (run/chain.h) gives `part`: when
/// it holds a mesh, the bodies the run starts from (scene::initial_state);
/// on return, the state the run ended with.
RunEnd run(const scene::Case& c, const RunOptions& options, scene::RunState* part = nullptr);

/// The folder a run of `c` writes to.
std::string output_directory(const scene::Case& c, const RunOptions& options);

} // namespace anvil::run
