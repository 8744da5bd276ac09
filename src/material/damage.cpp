#include "anvil/material/damage.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace anvil::material {

const std::vector<std::pair<std::string, DamageCriterion>>& damage_criterion_names() {
  static const std::vector<std::pair<std::string, DamageCriterion>> names = {
      {"cockcroft_latham", DamageCriterion::cockcroft_latham},
      {"oyane", DamageCriterion::oyane},
      {"ayada", DamageCriterion::ayada},
      {"brozzo", DamageCriterion::brozzo},
  };
  return names;
}

std::string to_string(DamageCriterion c) {
  for (const auto& [name, criterion] : damage_criterion_names())
    if (criterion == c) return name;
  return "unknown";
}

std::optional<DamageCriterion> damage_criterion(const std::string& name) {
  for (const auto& [n, criterion] : damage_criterion_names())
    if (n == name) return criterion;
  return std::nullopt;
}

DamageStress damage_stress(const Vec6& stress) {
  const Vec6 c = to_components(stress);
  Eigen::Matrix3d sigma;
  sigma << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal;
  principal.computeDirect(sigma, Eigen::EigenvaluesOnly);
  return {principal.eigenvalues()[2], (stress[0] + stress[1] + stress[2]) / 3.0, von_mises(stress)}; // ascending
}

double damage_weight(const DamageModel& model, const DamageStress& s) {
  // Below this σ̄ (MPa) the point carries no deviator worth weighing: a rigid
  // zone's round-off; its dε̄ is nil as well.
  if (s.equivalent < 1e-12) return 0.0;
  switch (model.criterion) {
  case DamageCriterion::cockcroft_latham:
    return std::max(s.largest, 0.0) / s.equivalent;
  case DamageCriterion::oyane:
    return 1.0 + s.mean / (model.oyane_a * s.equivalent);
  case DamageCriterion::ayada:
    return s.mean / s.equivalent;
  case DamageCriterion::brozzo:
    // σ1 − σm ≥ 0 always, and is 0 only for a hydrostatic stress (σ̄ = 0, above).
    return 2.0 * s.largest / (3.0 * (s.largest - s.mean));
  }
  return 0.0;
}

} // namespace anvil::material
