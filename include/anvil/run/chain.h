// A chain of operations (docs/chains.md): each operation runs into its own
// numbered folder from the part the one before left, and the chain's folder
// holds the whole story: anvil.pvd over every operation with the time
// running on, and summary.json with each operation's figures.
#pragma once
#include "anvil/run/Simulation.h"
#include "anvil/scene/Chain.h"

#include <string>

namespace anvil::run {

/// "02-upset": the folder of operation `k` (from 0) in the chain's.
std::string operation_folder(const scene::Chain& chain, int k);

/// Runs the operations of `chain` in order, each placed (scene::Placement)
/// and carrying the part's mesh and fields. With options.resume the
/// operations done are taken from their last checkpoint and the one under
/// way resumes from its own, so that the chain ends as the uninterrupted
/// one. Returns how the last operation run ended (a stopped or interrupted
/// operation ends the chain there). Throws as run() does.
RunEnd run_chain(const scene::Chain& chain, const RunOptions& options);

} // namespace anvil::run
