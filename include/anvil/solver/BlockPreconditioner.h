// Block-diagonal preconditioner for the condensed MINI system
//   A = [K  Bᵀ; B  −C],   P = diag(K̂, Ŝ)
// with K̂ an incomplete Cholesky factor of the velocity block and Ŝ the
// diagonal of C. For the MINI element C (the condensed bubble) scales like
// V/η per node, as the viscosity-weighted pressure mass that approximates the
// Schur complement B K⁻¹ Bᵀ does (Elman, Silvester, Wathen 2014, ch. 4), so
// Ŝ needs no material data. P is SPD, as MINRES requires.
#pragma once
#include "anvil/fem/Assembler.h"

#include <Eigen/IterativeLinearSolvers>
#include <vector>

namespace anvil::solver {

class BlockPreconditioner {
public:
  using StorageIndex = long;
  BlockPreconditioner() = default;

  /// Which free unknowns are pressures; set before compute().
  void set_pressure_mask(std::vector<char> is_pressure);

  // Eigen preconditioner interface (used by Eigen::MINRES).
  BlockPreconditioner& analyzePattern(const fem::SparseMatrix&) { return *this; }
  BlockPreconditioner& factorize(const fem::SparseMatrix& a);
  BlockPreconditioner& compute(const fem::SparseMatrix& a) { return factorize(a); }
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const;
  Eigen::ComputationInfo info() const { return info_; }

private:
  std::vector<char> is_pressure_;
  std::vector<long> velocity_index_, pressure_index_; ///< free index of each block row
  Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<long>> velocity_factor_;
  Eigen::VectorXd pressure_diagonal_inverse_;
  Eigen::ComputationInfo info_ = Eigen::Success;
};

} // namespace anvil::solver
