// The fold watch of the time loop (effect folds, docs/reading-a-run.md §5):
// after each increment, the bodies' surfaces meeting themselves, new folds
// logged and every fold kept in RunState::folds.
#pragma once
#include "anvil/contact/folds.h"
#include "anvil/core/Timers.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

namespace anvil::run {

/// After an accepted increment: scans the folds (contact::find_folds, the
/// mean boundary edge as the edge), adds a record (and a log
/// line) for each fold not within two edges of one already recorded, and
/// updates the others' position and largest area.
void watch_folds(const scene::Scene& scene, const scene::Discretisation& disc, scene::RunState& state, Timers& timers);

} // namespace anvil::run
