// What a run tells its user as it goes (anvil.log and the terminal): the
// header that says what is being solved and how, the progress line of each
// accepted increment, and the time the run has left.
#pragma once
#include "anvil/run/Increment.h"
#include "anvil/run/Simulation.h"
#include "anvil/scene/Discretisation.h"
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"

#include <cstddef>
#include <deque>
#include <string>
#include <utility>

namespace anvil::run {

/// The time a run has left (s): the pace (wall time per unit of progress)
/// over the last 10 increments, so that it follows the run as the contact
/// grows or the mesh is refined, and a remesh or a cut increment weighs one
/// in ten. The first 3 increments of a run (or of a resumed run) are left
/// out, their Newton counts are not the run's (the contact settles, the
/// first preconditioner is built); unknown (NaN) until 3 more are done.
class TimeLeft {
public:
  /// `progress` (0 to 1, TimeStepControl::progress) reached at wall time `now` (s).
  double update(double progress, double now);

private:
  static constexpr std::size_t kSettling = 4, kWindow = 10, kFirst = 3;
  std::size_t updates_ = 0;                      ///< calls so far: the start, then one per increment
  std::deque<std::pair<double, double>> points_; ///< (progress, wall time s) after each increment
};

/// The header: the case, bodies, boundary, dies, contact, model, effects,
/// unknowns, solver and processes, time loop.
void log_header(const scene::Scene& scene, const scene::Discretisation& disc, const scene::RunState& state,
                const RunOptions& options);

/// "  T 812..1143 C (heat 6 %)": the bodies' temperature range and the heat
/// step's share `heat_share` of the increment's wall time; empty when isothermal.
std::string temperature_text(const scene::RunState& state, double heat_share);

/// The progress line of an increment of heat alone (nothing moves) of `dt` s.
void log_heat_step(const scene::RunState& state, double dt, double time_left);

/// The progress line of an accepted increment (its columns are explained in
/// the README); `time_left` in s (NaN: unknown).
void log_progress(const scene::Scene& scene, const scene::Discretisation& disc, const scene::RunState& state,
                  const IncrementOutcome& inc, double time_left, double heat_share);

} // namespace anvil::run
