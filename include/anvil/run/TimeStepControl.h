// Δt of each increment, its cuts after a failure, and when the run stops
// (docs/design.md §4). The time loop asks it; it never solves anything.
#pragma once
#include "anvil/scene/RunState.h"
#include "anvil/scene/Scene.h"
#include "anvil/scene/TimeStep.h"

#include <optional>
#include <string>

namespace anvil::run {

/// Why a run stops.
struct Stop {
  std::string reason;   ///< empty while the run goes on
  bool complete = true; ///< false when it ends short of its stop criterion (`anvil run` exits with 4)
  explicit operator bool() const { return !reason.empty(); }
};

class TimeStepControl {
public:
  /// Reads the scene's time section; `scene` must outlive the control.
  explicit TimeStepControl(const scene::Scene& scene);

  /// The next increment from `state`: the nominal step, shortened so that no
  /// node moves more than max_displacement × its local element size (at the
  /// velocity of the last increment), and so that a stop criterion is met
  /// exactly, without a sliver of an increment before it.
  scene::TimeStep next_step(const scene::RunState& state) const;
  /// Δt after a failed try of `length`, or nothing when `cuts_done` halvings
  /// were made already (time.max_cuts).
  std::optional<double> cut(double length, int cuts_done) const;
  /// Whether a free node reaching a die at time `touch` (s) into `step` ends
  /// the increment there: not when it leaves a sliver of the step, below
  /// min_step_fraction of the planned Δt, before or after it.
  bool ends_at_contact(const scene::TimeStep& step, double touch) const;
  /// Whether and why the run stops at `state`: a stop criterion met
  /// (complete), or one that can no longer be met (a stroke die come to
  /// rest, dies that no longer close on a gap stop) or time.max_increments
  /// reached first (not complete).
  Stop stop(const scene::RunState& state) const;
  /// The stop criteria and where `state` stands against them, e.g.
  /// "final stroke 1 mm of die 'top', at 0.5 mm".
  std::string describe_stop(const scene::RunState& state) const;
  /// Fraction of the run done at `state` (the stop criterion nearest to being met).
  double progress(const scene::RunState& state) const;

private:
  /// Speed of the fastest moving part at the current press time (mm/s).
  double press_speed(const scene::RunState& state) const;

  const scene::Scene& scene_;
  const scene::TimeSpec& time_;
};

} // namespace anvil::run
