// The sparse direct solve of the condensed MINI system by MUMPS through
// PETSc: LDLᵀ with two-by-two pivoting (MUMPS SYM=2) while the tangent is
// symmetric, LU when a contact term makes it unsymmetric (Coulomb friction,
// quasi-symmetric pairs). The symbolic analysis is kept while the pattern is.
// PETSc options with the prefix direct_ reach it (-direct_mat_mumps_icntl_14 50).
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"

#include <memory>

namespace anvil::solver {

class MumpsSolver {
public:
  /// On the rows of `partition`; the matrix's creation timed in `timers`
  /// (both must outlive the solver). `workspace_percent`: MUMPS's ICNTL(14)
  /// to start from (0: MUMPS's default), a predecessor's workspace_percent().
  MumpsSolver(const fem::Partition& partition, Timers& timers, int workspace_percent = 0);
  ~MumpsSolver();
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  /// Factorises `a` (a view, no copy: `a` must stay in place until the next
  /// call). False when the factorisation fails (a singular tangent).
  bool factorize(const fem::SparseMatrix& a);
  /// x = A⁻¹ b with the last factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Symbolic analyses so far.
  int analyses() const { return analyses_; }
  /// ICNTL(14) as raised by a factorisation that ran out of workspace (0: MUMPS's default).
  int workspace_percent() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int analyses_ = 0;
};

} // namespace anvil::solver
