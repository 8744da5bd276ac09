// The direction of the deviatoric strain rate at each quadrature point as an
// unknown of Newton's own: a stress-velocity Newton (Rudi, Shih & Stadler
// 2020, G-cubed 21, e2020GC009059) for the power laws of the viscoplastic
// materials (docs/design.md §2).
//
// Norton-Hoff's stress s = 2η(ε̄̇) e, η ∝ ε̄̇^(m−1), written s = f(r) n with
// r = ε̄̇ = √(⅔ e:e), n = e/r and f = 2ηr ∝ r^m, has the consistent tangent
// 2η [P + (m−1) ⅔ n⊗n]. Along n it is m times the secant: a step that slows a
// point by more than the fraction m, or turns its rate round, overshoots
// and the line search halves it (rigid zones, a flash forming). With the
// direction as an unknown n̂ under the constraint n̂ r = e, Newton
// linearises in (v, n̂) and eliminates Δn̂: the residual is unchanged, the
// tangent's rank-one term takes n̂ in place of one n,
//   2η [P + (m−1) ⅔ sym(n̂ ⊗ n)],
// and n̂ follows its own linearised update from the last iterate k,
//   n̂ ← n̂ₖ + [Δe − n̂ₖ ⅔ (nₖ:Δe) + α (eₖ − n̂ₖ rₖ)]/rₖ,
// scaled back to ⅔ n̂:n̂ ≤ 1, which keeps the tangent positive definite
// (its quadratic form is at least m × 2η|Δe|²). Where the iterates settle,
// n̂ → n and Newton's quadratic end is kept.
#pragma once
#include "anvil/material/mandel.h"

#include <Eigen/Core>
#include <array>

namespace anvil::fem {

using DualDirection = Eigen::Matrix<float, 6, 1>; ///< n̂ (Mandel, -): its tangent needs no more digits

/// What one element needs of the dual: the unknowns of the last iterate and
/// n̂ there per quadrature point; it writes n̂ at the trial.
struct ElementDual {
  std::array<Eigen::Vector3d, 4> nodal_velocity; ///< at the last iterate (mm/s)
  Eigen::Vector3d bubble_velocity;               ///< at the last iterate
  double step = 0.0;                             ///< α: the trial is the last iterate + α × direction
  const DualDirection* last = nullptr;           ///< n̂ₖ per point; null: n̂ₖ = nₖ (Newton's first iterate)
  DualDirection* trial = nullptr;                ///< n̂ per point at the trial
};

/// n̂ at the trial of deviatoric rate `e` from the last iterate's `e_last` and
/// `dual_last` (null: n̂ₖ = nₖ).
inline material::Vec6 dual_direction(const material::Vec6& e, const material::Vec6& e_last,
                                     const DualDirection* dual_last, double step) {
  constexpr double kTwoThirds = 2.0 / 3.0;
  const double r_last = std::sqrt(kTwoThirds * e_last.squaredNorm());
  if (!(r_last > 0.0)) { // a point at rest: its direction is the trial's own
    const double r = std::sqrt(kTwoThirds * e.squaredNorm());
    return r > 0.0 ? material::Vec6(e / r) : material::Vec6::Zero();
  }
  const material::Vec6 n_last = e_last / r_last;
  const material::Vec6 dual = dual_last ? material::Vec6(dual_last->cast<double>()) : n_last;
  const material::Vec6 de = e - e_last;
  material::Vec6 next = dual + (de - dual * (kTwoThirds * n_last.dot(de)) + step * (e_last - dual * r_last)) / r_last;
  const double length = std::sqrt(kTwoThirds * next.squaredNorm());
  if (length > 1.0) next /= length;
  return next;
}

} // namespace anvil::fem
