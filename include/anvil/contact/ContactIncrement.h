// What a contact term (dies, body pairs) needs to know of the increment it
// is solved in: Δt, the penalty, the friction regularisation, the active-set
// hysteresis, and the per-node material scales of friction.
#pragma once
#include <algorithm>
#include <limits>
#include <vector>

namespace anvil::contact {

/// Per-increment constants of a contact term.
struct ContactIncrement {
  double time_step;      ///< Δt (s)
  double penalty;        ///< ρ (MPa·s/mm)
  double regularisation; ///< friction w₀ (mm/s)
  double gap_tolerance;  ///< mm/s: the active set changes at convergence only beyond ±this
  double recovery_time;  ///< s: a penetration present at the start is removed over at least this (the nominal Δt)
  double recovery_speed = std::numeric_limits<double>::infinity(); ///< mm/s: and no faster than this
  std::vector<double> flow_stress{}; ///< σ₀ per node (MPa), for Tresca (contact_scales)
  std::vector<double> consistency{}; ///< K per node, for Norton friction

  /// The time t over which a gap δ₀ (mm) is closed in the condition
  /// δ₀ + t (v − v_die)·n ≥ 0 (paper eq. 4, linearised): Δt for an open gap,
  /// at least the nominal step for a penetration, and at least |δ₀| over the
  /// recovery speed. A node left inside a die (by a remesh's put-back) is
  /// otherwise pushed out by |δ₀| in one increment at any Δt, so no
  /// time-step cut could save an element that push inverts; and a deep one
  /// pushed out fast drives a flow of its own that changes the press load.
  double closing_time(double gap) const {
    return gap < 0.0 ? std::max({time_step, recovery_time, -gap / recovery_speed}) : time_step;
  }
};

} // namespace anvil::contact
