// HDF5 checkpoints of a run (docs/libraries.md §4): what `--resume` reads,
// and the bytes in which rank 0 sends a remeshed state to the other
// processes.
#pragma once
#include "anvil/scene/RunState.h"

#include <string>
#include <vector>

namespace anvil::io {

/// Writes `state` and the case's `fingerprint` (Scene::fingerprint) to `path`
/// through a temporary file, flushed, then renamed, so a reader never sees a
/// torn checkpoint and a failed write leaves the one before in place. Throws
/// RunError.
void write_checkpoint(const std::string& path, const scene::RunState& state,
                      const std::vector<std::string>& fingerprint);
/// Reads a checkpoint written by write_checkpoint, checking every index and
/// size against its mesh and every number for finiteness. Throws InputError
/// naming the dataset and record.
scene::RunState read_checkpoint(const std::string& path);
/// Several processes (mpirun): every process takes rank 0's `state`, sent
/// as a checkpoint's bytes (after a remesh that rank 0 alone ran). Throws RunError.
void share_state(scene::RunState& state);
/// The case fingerprint a checkpoint was written with; empty for checkpoints
/// written before anvil kept it. Throws InputError.
std::vector<std::string> read_checkpoint_fingerprint(const std::string& path);

} // namespace anvil::io
