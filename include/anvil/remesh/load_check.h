// Load continuity across a remesh (remeshing.check_load), measured at equal
// geometry: the next increment solved on the old mesh and on the new. Their
// difference is the jump the remesh puts in the load-stroke curve.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/TimeStep.h"

namespace anvil::remesh {

/// Press load (N, the first load surface) of the increment `step` from
/// `state`, solved `solves` times in a row (each from the solution before,
/// which sets friction's σ₀ for the next) on a copy of the state with its
/// own discretisation and solver: neither `state` nor the run's solver is
/// touched. A contact event does not shorten the step. NaN when a solve fails.
double next_increment_load(const scene::Scene& scene, const scene::RunState& state, const scene::TimeStep& step,
                           int solves, Timers& timers);

} // namespace anvil::remesh
