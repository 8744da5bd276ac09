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

double damage_weight(const DamageModel& model, const Vec6& stress) {
  const double equivalent = von_mises(stress);
  // Below this σ̄ (MPa) the point carries no deviator worth weighing: a rigid
  // zone's round-off; its dε̄ is nil as well.
  if (equivalent < 1e-12) return 0.0;
  const double mean = (stress[0] + stress[1] + stress[2]) / 3.0;
  const Vec6 c = to_components(stress);
  Eigen::Matrix3d sigma;
  sigma << c[0], c[3], c[5], c[3], c[1], c[4], c[5], c[4], c[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal;
  principal.computeDirect(sigma, Eigen::EigenvaluesOnly);
  const double largest = principal.eigenvalues()[2]; // ascending
  switch (model.criterion) {
  case DamageCriterion::cockcroft_latham:
    return std::max(largest, 0.0) / equivalent;
  case DamageCriterion::oyane:
    return 1.0 + mean / (model.oyane_a * equivalent);
  case DamageCriterion::ayada:
    return mean / equivalent;
  case DamageCriterion::brozzo:
    // σ1 − σm ≥ 0 always, and is 0 only for a hydrostatic stress (σ̄ = 0, above).
    return 2.0 * largest / (3.0 * (largest - mean));
  }
  return 0.0;
}

} // namespace anvil::material
