// Friction laws between a body and a die (docs/design.md §3), as a tangential stress
// τ(w) resisting the sliding velocity w (mm/s, in the tangent plane):
//   Tresca     τ = m̄ σ₀/√3 · w/s
//   Coulomb    τ = min(μ σn, m̄ σ₀/√3) · w/s      (cap only when m̄ > 0)
//   Norton     τ = α K s^(q−1) w
//   sticking   τ = ρ w   (penalty on the tangential velocity)
// with the regularised slip s = sqrt(|w|² + w₀²), so τ is smooth at w = 0
// and Tresca/Norton derive from the convex potential c/(q+1) s^(q+1).
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>

namespace anvil::contact {

enum class FrictionKind { frictionless, sticking, tresca, coulomb, norton };

struct FrictionLaw {
  FrictionKind kind = FrictionKind::frictionless;
  double tresca_factor = 0.0; ///< m̄ (Tresca; Coulomb cap when > 0), 0..1
  double coefficient = 0.0;   ///< μ (Coulomb) or α (Norton)
  double exponent = 0.0;      ///< q (Norton), 0 < q ≤ 1
};

/// What the contact term needs of the law at one node.
struct FrictionInput {
  Eigen::Vector3d sliding; ///< w = tangential relative velocity body − die (mm/s)
  double normal_pressure;  ///< σn ≥ 0 (MPa)
  double flow_stress;      ///< σ₀ (MPa), for Tresca
  double consistency;      ///< K (MPa·s^q), for Norton
  double regularisation;   ///< w₀ (mm/s)
  double penalty;          ///< ρ (MPa·s/mm), for sticking
  /// The tangent ∂τ/∂w is built with the exponent max(q, this) along w (0:
  /// the consistent tangent); Newton's far phase (IncrementSolver).
  double tangent_sensitivity_floor = 0.0;
  /// Newton's own sliding direction λ (contact/FrictionDual.h): the tangent's
  /// rank-one term along w is built with it; none: with w/s.
  std::optional<Eigen::Vector3d> direction;
};

struct FrictionStress {
  Eigen::Vector3d stress;            ///< τ (MPa), along w: the force on the body is −τ × area
  Eigen::Matrix3d d_sliding;         ///< ∂τ/∂w (MPa·s/mm)
  Eigen::Vector3d d_normal_pressure; ///< ∂τ/∂σn (-), non-zero for uncapped Coulomb
};

/// True when τ is linear in w (frictionless, sticking).
inline bool is_linear(const FrictionLaw& law) {
  return law.kind == FrictionKind::frictionless || law.kind == FrictionKind::sticking;
}

FrictionStress friction_stress(const FrictionLaw& law, const FrictionInput& in);

std::string describe(const FrictionLaw& law);

} // namespace anvil::contact
