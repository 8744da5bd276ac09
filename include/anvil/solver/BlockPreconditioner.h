// Block-diagonal preconditioner for the condensed MINI system
//   A = [K  Bᵀ; B  −C],   P = diag(K_xx, K_yy, K_zz, Ŝ)
// - velocity: the three per-component diagonal blocks of K, each factorised
//   exactly (CHOLMOD supernodal Cholesky). By Korn's inequality this
//   "separate displacement component" preconditioner is spectrally
//   equivalent to K (Blaheta 1994, Numer. Linear Algebra Appl. 1, 107-128),
//   so MINRES iterations do not grow with the mesh the way IC(0) lets them;
// - pressure: Ŝ = diag(C). For the MINI element C (the condensed bubble)
//   scales like V/η per node, as the viscosity-weighted pressure mass that
//   approximates the Schur complement B K⁻¹ Bᵀ (Elman, Silvester, Wathen
//   2014, ch. 4), so Ŝ needs no material data.
// P is SPD, as MINRES requires.
#pragma once
#include "anvil/fem/Assembler.h"

#include <Eigen/CholmodSupport>
#include <array>
#include <memory>
#include <vector>

namespace anvil::solver {

class BlockPreconditioner {
public:
  using StorageIndex = int;
  BlockPreconditioner() = default;

  /// Component of each free unknown: 0, 1, 2 velocity x, y, z; 3 pressure. Set before compute().
  void set_components(std::vector<char> component);

  // Eigen preconditioner interface (used by Eigen::MINRES).
  BlockPreconditioner& analyzePattern(const fem::SparseMatrix&) { return *this; }
  BlockPreconditioner& factorize(const fem::SparseMatrix& a);
  BlockPreconditioner& compute(const fem::SparseMatrix& a) { return factorize(a); }
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;
  Eigen::ComputationInfo info() const { return info_; }

private:
  using Block = Eigen::SparseMatrix<double, Eigen::ColMajor, long>;
  using Cholesky = Eigen::CholmodSupernodalLLT<Block, Eigen::Lower>;
  std::vector<char> component_;
  std::array<std::vector<long>, 4> index_;                   ///< free indices of each component
  std::array<std::unique_ptr<Cholesky>, 3> velocity_factor_; ///< symbolic analysis kept across Newton iterations
  Eigen::VectorXd pressure_diagonal_inverse_;
  Eigen::ComputationInfo info_ = Eigen::Success;
};

} // namespace anvil::solver
