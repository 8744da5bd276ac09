// The sliding direction λ = w/s (s = √(|w|² + w₀²)) of each contact point as
// an unknown of Newton's own (docs/design.md §3): a primal-dual Newton for
// regularised friction, the device Chan, Golub & Mulet (1999, SIAM J. Sci.
// Comput. 20) gave the like nonlinearity of total variation, and Rudi, Shih &
// Stadler (2020, G-cubed 21) viscoplastic Stokes flow.
//
// Regularised Tresca or Coulomb friction τ = c w/s has, along w, the
// consistent tangent c w₀²/s³: a step that must slow or turn a sliding node
// sees almost no stiffness there and overshoots, and the line search halves
// it. Written as τ = c λ with the constraint λ s = w, Newton linearises in
// (w, λ) and eliminates Δλ: the residual is unchanged, the tangent's rank-one
// term takes λ in place of one w/s, c s^(q−1) [I + (q−1) sym(λ ⊗ w)/s], and
// λ follows its own linearised update,
//   λ ← λ + [Δw − λ (w·Δw)/s + α (w − λ s)]/s   (all at the last iterate),
// scaled back to |λ| ≤ 1, which keeps the tangent positive semi-definite.
// Where the iterates settle λ → w/s and Newton's quadratic end is kept.
#pragma once
#include <Eigen/Core>

#include <vector>

namespace anvil::contact {

class FrictionDual {
public:
  /// At Newton's starting iterate: λ = w/s at each point, `sliding[i]` = w.
  void start(const std::vector<Eigen::Vector3d>& sliding, double regularisation);
  /// The line search's trial is the last iterate plus `step` × the Newton
  /// direction (0: the last iterate itself).
  void set_step(double step) { step_ = step; }
  /// λ of point `i` at the trial whose sliding velocity is `w`.
  Eigen::Vector3d direction(int i, const Eigen::Vector3d& w) const;
  /// The trial with these sliding velocities is Newton's next iterate.
  void accept(const std::vector<Eigen::Vector3d>& sliding);
  bool empty() const { return direction_.empty(); }

private:
  std::vector<Eigen::Vector3d> direction_; ///< λ at the last iterate
  std::vector<Eigen::Vector3d> sliding_;   ///< w at the last iterate (mm/s)
  double regularisation_ = 0.0;            ///< w₀ (mm/s)
  double step_ = 0.0;
};

} // namespace anvil::contact
