// The lengths of one increment, as the time loop plans and cuts it
// (TimeStepControl) and as an increment, a remesh and the load check use it.
#pragma once

namespace anvil::scene {

/// The lengths of one increment (s).
struct TimeStep {
  /// The stroke increment at the current press speed: contact recovery and
  /// volume compensation act over at least this, whatever Δt is.
  double nominal = 0.0;
  double planned = 0.0; ///< Δt chosen for the increment, before contact events and cuts
  double length = 0.0;  ///< Δt tried
};

} // namespace anvil::scene
