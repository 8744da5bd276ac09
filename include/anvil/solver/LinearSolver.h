// Sparse direct solvers for the condensed system (symmetric quasi-definite,
// DESIGN §2). The symbolic analysis is done once and reused while the
// pattern is unchanged (call pattern_changed() after a remesh or contact change).
#pragma once
#include "anvil/fem/Assembler.h"

#include <memory>
#include <string>

namespace anvil::solver {

enum class LinearSolverKind {
  umfpack,         ///< SuiteSparse UMFPACK LU (pivoting; copes with indefinite and unsymmetric tangents)
  cholmod_ldlt,    ///< SuiteSparse CHOLMOD simplicial LDLᵀ (no pivoting; quasi-definite only)
  eigen_ldlt,      ///< Eigen SimplicialLDLT with AMD (no pivoting; quasi-definite only)
};

LinearSolverKind linear_solver_kind(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(LinearSolverKind kind);

class LinearSolver {
public:
  explicit LinearSolver(LinearSolverKind kind);
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Factorises `a` (symbolic analysis only on the first call or after
  /// pattern_changed()). Returns false when the factorisation fails.
  bool factorize(const fem::SparseMatrix& a);
  /// x = A⁻¹ b with the last factorisation; false on failure.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  void pattern_changed() { analysed_ = false; }

  LinearSolverKind kind() const { return kind_; }
  int analyses() const { return analyses_; }

private:
  struct Backend;
  LinearSolverKind kind_;
  std::unique_ptr<Backend> backend_;
  bool analysed_ = false;
  int analyses_ = 0;
};

} // namespace anvil::solver
