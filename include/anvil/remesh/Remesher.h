// Remeshing in the time loop: making the new mesh of a body due for one
// (remesh_due.h): CGAL's mesh of the deformed body, the fields transferred
// onto it, its boundary put onto the dies and its material given back
// (fit_to_dies), each remesh recorded in the run state.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/remesh/remesh_due.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <span>
#include <string>
#include <vector>

namespace anvil::remesh {

/// Remeshes the bodies of `due` in `state`: a new mesh, the nodal (v, p)
/// interpolated (the next Newton guess), ε̄ remapped conservatively, the
/// boundary fitted to the dies, a RemeshRecord per body, the volume budget
/// and inside_dies updated. `touching_die` (per node of state.mesh: the die
/// it presses on, or −1) and `rate` (ε̄̇ per element of state.mesh) are those
/// of the increment just accepted. The run must then be discretised again.
/// `next_step` (s) is the length of the increment that follows, which the
/// remesh looks ahead over (elements that would invert in it). Several processes: rank 0
/// remeshes and sends the new state to the others (io::share_state).
void remesh(const scene::Scene& scene, scene::RunState& state, std::span<const RemeshDue> due,
            std::span<const int> touching_die, std::span<const double> rate, double next_step, Timers& timers);

} // namespace anvil::remesh
