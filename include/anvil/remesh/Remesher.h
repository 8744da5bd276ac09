// Remeshing in the time loop: when a body needs a new mesh (remesh_due),
// and making it (remesh_bodies): CGAL's mesh of the deformed body, the
// fields transferred onto it, its boundary put onto the dies and its
// material given back (fit_to_dies), each remesh recorded in the run state.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <span>
#include <string>
#include <vector>

namespace anvil::remesh {

/// A body due for a remesh, and why (for the log).
struct RemeshDue {
  int body;
  std::string why;
  /// remeshing.local and a trigger that a local remesh may meet: poor
  /// elements (now or in the next increment). A die corner sunk into the
  /// body or its overlap with the dies needs new surface nodes, and a
  /// periodic remesh is of the whole body: they remesh the whole body.
  bool local = false;
};

/// The bodies of `state` to remesh after an increment of `dt` (s), by the
/// case's triggers: worst quality below remeshing.quality, an element that
/// would invert in a next increment alike, every N increments, a die vertex
/// deeper than die_penetration × the element size inside the body, more than
/// die_overlap × its initial volume inside the dies (each of the last two
/// again only once it has grown by half its trigger beyond what the body's
/// last remesh left: a remesh that cannot fit a die does not repeat). Elastic
/// bodies keep their mesh. Logs each body's quality.
std::vector<RemeshDue> remesh_due(const scene::Scene& scene, const scene::RunState& state, double dt);

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
