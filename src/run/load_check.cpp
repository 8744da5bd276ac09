#include "anvil/run/load_check.h"

#include "anvil/core/log.h"
#include "anvil/run/Increment.h"
#include "anvil/scene/Discretisation.h"

#include <cmath>
#include <limits>
#include <optional>

namespace anvil::run {

using namespace scene; // the loop runs on the scene's types throughout

double next_increment_load(const scene::Scene& scene, const scene::RunState& state, const scene::TimeStep& step,
                           int solves, Timers& timers) {
  Timers::Scope scope(timers, "load check");
  scene::RunState copy = state;
  scene::Discretisation disc = scene::discretise(scene, copy, timers);
  double load = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < solves; ++k) {
    IncrementOutcome inc = solve_increment(scene, disc, copy, step, timers, ContactEvents::ignore);
    if (!inc.converged()) return std::numeric_limits<double>::quiet_NaN();
    load = std::abs(inc.forces.front().z()); // the press load, as LoadRecord::press_load
    copy.unknowns = std::move(inc.unknowns);
  }
  return load;
}

namespace {

/// After a remesh for another trigger, with remeshing.split_sunk_edges, the
/// edges its new mesh leaves sunk over a die feature are split in the same
/// step: a whole remesh resamples the surface at the body's size and drops
/// the nodes earlier splits had put onto the die edges, and remesh_due looks
/// for sunk edges only in an increment with no other trigger.
void split_sunk_edges_after(const Scene& scene, RunState& state, std::span<const remesh::RemeshDue> due,
                            const TimeStep& next, Timers& timers) {
  std::vector<remesh::RemeshDue> splits;
  for (const remesh::RemeshDue& d : due)
    if (d.sunk_edges.empty())
      if (std::optional<remesh::RemeshDue> split = remesh::sunk_edges_due(scene, state, d.body)) {
        split->why = "after that remesh, " + split->why;
        splits.push_back(std::move(*split));
      }
  if (splits.empty()) return;
  // The dies each new node presses on, from the velocity carried onto it;
  // no strain rates: a split takes no size field.
  const Discretisation disc = discretise(scene, state, timers);
  remesh::remesh(scene, state, splits, disc.touching_die(state.unknowns.nodal), {}, next.length, timers);
}

} // namespace

void remesh_checking_load(const Scene& scene, RunState& state, std::span<const remesh::RemeshDue> due,
                          std::span<const int> touching_die, std::span<const double> rate, const TimeStep& next,
                          Timers& timers) {
  const bool check = scene.input.remeshing.check_load && !scene.surfaces.empty();
  const double old_mesh = check ? next_increment_load(scene, state, next, 1, timers) : 0.0;
  const std::size_t first_record = state.remeshes.size();
  remesh::remesh(scene, state, due, touching_die, rate, next.length, timers);
  const std::size_t first_split = state.remeshes.size();
  split_sunk_edges_after(scene, state, due, next, timers);
  if (!check || state.remeshes.size() == first_record) return; // no body took a new mesh: nothing to compare
  // Twice on the new mesh: friction takes σ₀ from the strain rates of the
  // solution before, at first the interpolated velocity; the second solve
  // takes them from the first, as the next increment will.
  const double new_mesh = next_increment_load(scene, state, next, 2, timers);
  // The jump is the remesh's, splits after it included; a split alone carries it when it was all.
  const std::size_t end = first_split > first_record ? first_split : state.remeshes.size();
  for (std::size_t r = first_record; r < end; ++r)
    state.remeshes[r].load_old_mesh = old_mesh, state.remeshes[r].load_new_mesh = new_mesh;
  if (std::isnan(old_mesh) || std::isnan(new_mesh))
    log::info("    load check: the next increment (dt %.3g s) did not converge on the %s mesh; not measured",
              next.length, std::isnan(old_mesh) ? "old" : "new");
  else
    log::info("    load check, next increment (dt %.3g s) on the old mesh and on the new: %.5g and %.5g kN (%+.2f%%)",
              next.length, old_mesh / 1e3, new_mesh / 1e3, 100.0 * state.remeshes[first_record].load_jump());
}

} // namespace anvil::run
