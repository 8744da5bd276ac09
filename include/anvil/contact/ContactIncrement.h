// What a contact term (dies, body pairs) needs to know of the increment it
// is solved in: Δt, the penalty, the friction regularisation, the active-set
// hysteresis, and the per-node material scales of friction.
#pragma once
#include <vector>

namespace anvil::contact {

/// Per-increment constants of a contact term.
struct ContactIncrement {
  double time_step;       ///< Δt (s)
  double penalty;         ///< ρ (MPa·s/mm)
  double regularisation;  ///< friction w₀ (mm/s)
  double gap_tolerance;   ///< mm/s: the active set changes at convergence only beyond ±this
  const std::vector<double>* flow_stress = nullptr; ///< σ₀ per node (MPa), for Tresca
  const std::vector<double>* consistency = nullptr; ///< K per node, for Norton friction
};

} // namespace anvil::contact
