#include "anvil/contact/Friction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace anvil::contact {

FrictionStress friction_stress(const FrictionLaw& law, const FrictionInput& in) {
  FrictionStress out{Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), Eigen::Vector3d::Zero()};
  const Eigen::Vector3d& w = in.sliding;
  if (law.kind == FrictionKind::frictionless) return out;
  if (law.kind == FrictionKind::sticking) {
    out.stress = in.penalty * w;
    out.d_sliding = in.penalty * Eigen::Matrix3d::Identity();
    return out;
  }
  // τ = c s^(q−1) w;  ∂τ/∂w = c [s^(q−1) I + (q−1) s^(q−3) w wᵀ].
  double c = 0.0, q = 0.0;
  const double tresca = law.tresca_factor * in.flow_stress / std::sqrt(3.0);
  bool coulomb_uncapped = false;
  switch (law.kind) {
  case FrictionKind::tresca:
    c = tresca;
    break;
  case FrictionKind::coulomb:
    c = law.coefficient * in.normal_pressure;
    coulomb_uncapped = !(law.tresca_factor > 0.0 && c > tresca);
    if (!coulomb_uncapped) c = tresca;
    break;
  case FrictionKind::norton:
    c = law.coefficient * in.consistency;
    q = law.exponent;
    break;
  default:
    break;
  }
  const double s = std::sqrt(w.squaredNorm() + in.regularisation * in.regularisation);
  const double sq1 = std::pow(s, q - 1.0);
  out.stress = c * sq1 * w;
  // Along w the consistent tangent is q times the secant one (zero for
  // Tresca and Coulomb): a floor on q stiffens it there, τ itself unchanged.
  const double q_t = std::max(q, in.tangent_sensitivity_floor);
  const Eigen::Matrix3d along = in.direction ? 0.5 * s * (*in.direction * w.transpose() + w * in.direction->transpose())
                                             : Eigen::Matrix3d(w * w.transpose());
  out.d_sliding = c * (sq1 * Eigen::Matrix3d::Identity() + (q_t - 1.0) * sq1 / (s * s) * along);
  if (coulomb_uncapped) out.d_normal_pressure = law.coefficient * sq1 * w;
  return out;
}

std::string describe(const FrictionLaw& law) {
  char text[160];
  switch (law.kind) {
  case FrictionKind::frictionless:
    return "frictionless";
  case FrictionKind::sticking:
    return "sticking";
  case FrictionKind::tresca:
    std::snprintf(text, sizeof text, "Tresca, m = %g", law.tresca_factor);
    break;
  case FrictionKind::coulomb:
    if (law.tresca_factor > 0.0)
      std::snprintf(text, sizeof text, "Coulomb, mu = %g, capped by Tresca m = %g", law.coefficient, law.tresca_factor);
    else
      std::snprintf(text, sizeof text, "Coulomb, mu = %g", law.coefficient);
    break;
  case FrictionKind::norton:
    std::snprintf(text, sizeof text, "viscoplastic (Norton), alpha = %g, q = %g", law.coefficient, law.exponent);
    break;
  }
  return text;
}

} // namespace anvil::contact
