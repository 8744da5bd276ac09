// Load continuity across a remesh (remeshing.check_load), measured at equal
// geometry: the next increment solved on the old mesh and on the new. Their
// difference is the jump the remesh puts in the load-stroke curve.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/remesh/Remesher.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/TimeStep.h"

namespace anvil::run {

/// Press load (N, the first load surface) of the increment `step` from
/// `state`, solved `solves` times in a row (each from the solution before,
/// which sets friction's σ₀ for the next) on a copy of the state with its
/// own discretisation and solver: neither `state` nor the run's solver is
/// touched. A contact event does not shorten the step. NaN when a solve fails.
double next_increment_load(const scene::Scene& scene, const scene::RunState& state, const scene::TimeStep& step,
                           int solves, Timers& timers);

/// remesh::remesh before the increment `next`, and with remeshing.check_load
/// the press load of `next` solved on the old mesh and on the new one in
/// the records (a measurement, on copies: the run goes on as without it).
void remesh_checking_load(const scene::Scene& scene, scene::RunState& state, std::span<const remesh::RemeshDue> due,
                          std::span<const int> touching_die, std::span<const double> rate, const scene::TimeStep& next,
                          Timers& timers);

} // namespace anvil::run
