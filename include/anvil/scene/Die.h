// A rigid die of a scene, built from its DieSpec: surface, press motion,
// friction, and how it advances in time (docs/design.md §4).
#pragma once
#include "anvil/die/DieSurface.h"
#include "anvil/die/EnergyPress.h"
#include "anvil/die/PressKinematics.h"
#include "anvil/scene/Case.h"
#include "anvil/scene/RunState.h"

#include <memory>
#include <optional>

namespace anvil::scene {

struct Die {
  std::string name;
  std::unique_ptr<die::DieSurface> surface;
  std::unique_ptr<die::PressKinematics> kinematics;            ///< null for a fixed die
  double load_limit = std::numeric_limits<double>::infinity(); ///< N (hydraulic, screw press)
  /// A hammer or screw press: `kinematics` moves at its impact speed, and
  /// DieState::speed_factor follows the energy left (run/blows.h).
  std::optional<die::EnergyPress> energy;
  /// Die wear (effect die_wear), its hardness at the die's temperature.
  std::optional<contact::WearLaw> wear;
  /// A worn die's triangles refined to the part's sampling size
  /// (die::refine): its wear needs vertices where an STL's flat faces have none.
  std::optional<die::SurfaceTriangles> refined;

  /// The triangles the die is written and measured on (VTK series, die fill,
  /// die wear), in its start position: its surface's, or `refined`.
  const die::SurfaceTriangles& shown() const { return refined ? *refined : surface->triangles(); }
  /// Where the die's fill is measured (its 'fill' key; none without it).
  contact::FillSamples fill_samples;
  contact::FrictionLaw friction;

  /// Mean velocity over [t, t + Δt] from state `s` (mm/s).
  Eigen::Vector3d velocity(const DieState& s, double time_step) const;
  /// True when the die will not move again from state `s` (fixed, or its
  /// motion over: PressKinematics::rest_time).
  bool at_rest_for_good(const DieState& s) const { return !kinematics || s.press_time >= kinematics->rest_time(); }
  /// Moves the die by one increment of length Δt.
  void advance(DieState& s, double time_step) const;
  /// Load-limited press: after an increment with load `resisting` (N, the
  /// load component against the motion), scales press speed so the load
  /// would be at the limit, for a body of rate sensitivity m (load ∝ v^m).
  void limit_speed(DieState& s, double resisting, double rate_sensitivity) const;
};

/// Builds a die; `body_size` (mm) sizes the display square of plane dies,
/// `sampling` (mm) is the longest edge of a worn die's refined triangles.
/// Throws InputError naming the case line for a bad STL surface or a wear
/// card without a hardness table.
Die build_die(const DieSpec& spec, double body_size, double sampling);

} // namespace anvil::scene
