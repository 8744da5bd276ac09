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

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace anvil::contact {

class FrictionDual {
public:
  /// At Newton's starting iterate: λ = w/s at each of `count` points, w =
  /// `sliding(i)`.
  template <class Sliding> void start(std::size_t count, const Sliding& sliding, double regularisation) {
    regularisation_ = regularisation;
    sliding_.resize(count);
    direction_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      sliding_[i] = sliding(i);
      const double s = std::sqrt(sliding_[i].squaredNorm() + regularisation * regularisation);
      direction_[i] = s > 0.0 ? Eigen::Vector3d(sliding_[i] / s) : Eigen::Vector3d::Zero();
    }
    step_ = 0.0;
  }
  /// The line search's trial is the last iterate plus `step` × the Newton
  /// direction (0: the last iterate itself).
  void set_step(double step) { step_ = step; }
  /// λ of point `i` at the trial whose sliding velocity is `w`; none before
  /// start() (the consistent tangent).
  std::optional<Eigen::Vector3d> direction(std::size_t i, const Eigen::Vector3d& w) const;
  /// The trial whose sliding velocities are `sliding(i)` is Newton's next iterate.
  template <class Sliding> void accept(const Sliding& sliding) {
    for (std::size_t i = 0; i < sliding_.size(); ++i) {
      const Eigen::Vector3d w = sliding(i);
      direction_[i] = *direction(i, w);
      sliding_[i] = w;
    }
    step_ = 0.0;
  }

private:
  std::vector<Eigen::Vector3d> direction_; ///< λ at the last iterate
  std::vector<Eigen::Vector3d> sliding_;   ///< w at the last iterate (mm/s)
  double regularisation_ = 0.0;            ///< w₀ (mm/s)
  double step_ = 0.0;
};

} // namespace anvil::contact
