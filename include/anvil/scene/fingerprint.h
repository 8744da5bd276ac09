// What a resumed run compares with the run it continues: the case as
// "key = value" lines, with its material cards, mesh files and STL dies.
#pragma once
#include "anvil/scene/Case.h"

#include <string>
#include <vector>

namespace anvil::scene {

/// The fingerprint of `c`: every key of the case file as "key = value"
/// (Case::settings, overrides applied), every key of each body's material card as
/// "bodies[i].material (card.yaml): key = value", and a hash of each mesh file
/// and STL die ("bodies[i].mesh.file contents = …"). Left out, as a resumed run
/// may change them freely: title, output.*, time.stop.*, time.max_increments
/// and the linear solver's choices (solver.linear_solver, schur,
/// krylov_tolerance, reuse_preconditioner, petsc_options). Throws InputError
/// when a file cannot be read.
std::vector<std::string> case_fingerprint(const Case& c);

/// What differs from `before` to `now`, one "key: old -> new" per change
/// ("(absent)" for a key on one side only), in key order.
std::vector<std::string> fingerprint_changes(const std::vector<std::string>& before,
                                             const std::vector<std::string>& now);

} // namespace anvil::scene
