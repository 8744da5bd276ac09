// Ductile damage criteria: a damage value D = ∫ f(σ) dε̄ accumulated along
// the path of each material point, the crack predicted where D reaches the
// material's critical value. Each criterion is its weight f(σ) on the
// equivalent strain increment (docs/method.md, "Ductile damage"):
//   normalized Cockcroft-Latham  f = max(σ1, 0) / σ̄            (Oh, Chen, Kobayashi 1979)
//   Oyane                        f = 1 + σm / (a σ̄)             (Oyane, Sato, Okimoto, Shima 1980)
//   Ayada                        f = σm / σ̄                     (Ayada, Higashino, Mori 1987)
//   Brozzo                       f = 2 σ1 / (3 (σ1 − σm))       (Brozzo, Deluca, Rendina 1972)
// σ1 the largest principal stress, σm the mean stress, σ̄ von Mises' stress.
#pragma once
#include "anvil/material/mandel.h"

#include <optional>
#include <string>
#include <vector>

namespace anvil::material {

enum class DamageCriterion { cockcroft_latham, oyane, ayada, brozzo };

/// The criteria's names as the case file and the outputs spell them.
const std::vector<std::pair<std::string, DamageCriterion>>& damage_criterion_names();
std::string to_string(DamageCriterion c);
std::optional<DamageCriterion> damage_criterion(const std::string& name);

/// One criterion a run integrates, with its material constant (Oyane's a;
/// unused by the others).
struct DamageModel {
  DamageCriterion criterion = DamageCriterion::cockcroft_latham;
  double oyane_a = 0.0;
};

/// What every criterion reads of a stress (MPa): largest principal σ1, mean
/// σm, von Mises σ̄. Computed once per element for all the criteria asked.
struct DamageStress {
  double largest = 0.0, mean = 0.0, equivalent = 0.0;
};
DamageStress damage_stress(const Vec6& stress);

/// f(σ) of `model`: dD = f dε̄. Zero where the stress has no deviator
/// (σ̄ = 0: no plastic flow to weigh).
double damage_weight(const DamageModel& model, const DamageStress& s);
/// The same at the Cauchy stress `stress` (Mandel, MPa).
inline double damage_weight(const DamageModel& model, const Vec6& stress) {
  return damage_weight(model, damage_stress(stress));
}

} // namespace anvil::material
