// One increment of the time loop (docs/design.md §4): solve it on the current
// geometry, then accept it. Solving leaves the run state untouched, and
// accepting is all-or-nothing, so a failed try is simply dropped.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/element_fields.h"
#include "anvil/run/TimeStepControl.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/TimeStep.h"

#include <span>
#include <string>
#include <vector>

namespace anvil::run {

/// An increment solved and not yet accepted.
struct IncrementOutcome {
  double time_step = 0.0;     ///< s, as solved (a contact event may end it before the step tried)
  fem::BodyUnknowns unknowns; ///< the solution
  solver::NewtonReport report;
  std::vector<Eigen::Vector3d> forces; ///< N, on each load surface (scene::Scene::surfaces) at the solution
  double compensation = 0.0;           ///< mm³ the volume compensation asked the flow to restore
  /// ε̄̇ and σ per element on the geometry solved on (converged only): what
  /// ε̄ and elastic bodies integrate, and what the remeshing size field reads.
  fem::ElementFields fields;
  std::string failure; ///< why it cannot be accepted; empty when it can
  int couplings = 0;   ///< iterated heat coupling: flow solves redone with the increment's end temperatures

  bool converged() const { return report.converged; }
};

/// What a free node that reaches a die within the step does.
enum class ContactEvents {
  end_increment, ///< the increment is solved again up to that moment (TimeStepControl::ends_at_contact)
  ignore         ///< the step is kept (a measurement at a given Δt)
};

/// Solves the increment `step` from `state` (its unknowns are the Newton
/// guess, or `guess` when given): contact search, contact scales, volume
/// compensation, Newton on (v, p). Uses `disc`'s contact terms and solver;
/// `state` is not changed.
IncrementOutcome solve_increment(const scene::Scene& scene, scene::Discretisation& disc, const scene::RunState& state,
                                 const scene::TimeStep& step, Timers& timers,
                                 ContactEvents events = ContactEvents::end_increment,
                                 const fem::BodyUnknowns* guess = nullptr);

/// solve_increment in the time loop. In a thermal scene with
/// thermal.coupling_tolerance > 0 (iterated coupling) the flow is solved
/// again with the element temperatures the increment's heat step predicts,
/// until they change by less than the tolerance (°C), 5 times at most (then
/// the increment fails and is cut); otherwise (staggered) the flow sees T_n.
IncrementOutcome solve_coupled(const scene::Scene& scene, scene::Discretisation& disc, const scene::RunState& state,
                               const scene::TimeStep& step, Timers& timers, const fem::BodyUnknowns* guess = nullptr);

/// Accepts a converged increment into `state`: x ← x + Δt v, the dies
/// moved, contact nodes projected onto them, the loads recorded (at the
/// stroke and time where the increment starts: they were solved on that
/// geometry, as loads.csv's row of that increment count), ε̄ and the
/// stress of elastic bodies updated, a load-limited press slowed down.
/// Returns false, with `inc.failure` set and `state` untouched, when an
/// element would invert.
bool accept_increment(const scene::Scene& scene, scene::Discretisation& disc, IncrementOutcome& inc,
                      scene::RunState& state, Timers& timers);

/// The time loop's retry policy, as one call: the increment `step` from
/// `state` solved and accepted, retried on failure.
struct Advance {
  enum class End { accepted, interrupted, failed };
  End end;
  IncrementOutcome increment; ///< accepted: what went into `state`; failed: `failure` says why
};
/// A failed try leaves `state` as it was. Newton that ran out of iterations
/// while its residual fell goes on from where it stopped: once with the same
/// Δt (a cut would put this run's increments at other strokes than a run
/// whose round-off let Newton finish in its budget), then with half the Δt
/// tried (the flow hardly depends on Δt: from rest, not at all; starting
/// again from the state would walk the same path). Other failures halve Δt,
/// time.max_cuts times at most (`clock`), each retry logged.
Advance advance(const scene::Scene& scene, scene::Discretisation& disc, scene::RunState& state,
                const TimeStepControl& clock, scene::TimeStep step, Timers& timers);

/// Thermal scenes: the heat step over the increment just accepted
/// (staggered: the next increment's flow sees its temperatures).
void advance_heat(const scene::Scene& scene, scene::Discretisation& disc, const IncrementOutcome& inc,
                  scene::RunState& state, Timers& timers);

/// Thermal scenes: `steps` heat steps of `dt` s without flow (nothing moves):
/// the bodies cool in air and exchange heat with the dies and each other
/// where they touch.
void heat_alone(const scene::Scene& scene, scene::Discretisation& disc, scene::RunState& state, double dt, int steps,
                Timers& timers);

/// Thermal scenes: the transfer before the press moves (thermal.transfer_time),
/// in thermal.transfer_steps heat steps without flow.
void transfer(const scene::Scene& scene, scene::Discretisation& disc, scene::RunState& state, Timers& timers);

/// The stroke (mm) of load surface `surface` with the dies at `dies` at
/// time `time` (s): a die's travel, or a velocity plate's.
double surface_stroke(const scene::Scene& scene, std::span<const scene::DieState> dies, int surface, double time);

/// The loads at the geometry a run ends on (its last row of loads.csv: the
/// load at the final stroke, solved over a step `dt` s and not accepted).
void record_final_loads(const scene::Scene& scene, scene::Discretisation& disc, scene::RunState& state, double dt,
                        Timers& timers);

/// Accepts the solution of a case without a time loop: increment 1 at t = 0,
/// the geometry as it is.
void accept_without_motion(const scene::Scene& scene, const IncrementOutcome& inc, scene::RunState& state,
                           Timers& timers);

} // namespace anvil::run
