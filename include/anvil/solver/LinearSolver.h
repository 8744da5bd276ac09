// Sparse direct solvers for the condensed system (symmetric quasi-definite,
// DESIGN §2). The symbolic analysis is done once and reused while the
// pattern is unchanged (call pattern_changed() after a remesh or contact change).
#pragma once
#include "anvil/fem/Assembler.h"

#include <memory>
#include <string>
#include <vector>

namespace anvil::solver {

enum class LinearSolverKind {
  umfpack,         ///< SuiteSparse UMFPACK LU (pivoting; copes with indefinite and unsymmetric tangents)
  cholmod_ldlt,    ///< SuiteSparse CHOLMOD simplicial LDLᵀ (no pivoting; quasi-definite only)
  eigen_ldlt,      ///< Eigen SimplicialLDLT with AMD (no pivoting; quasi-definite only)
  minres,          ///< MINRES with the block-diagonal preconditioner (large meshes)
  automatic,       ///< umfpack up to kDirectSolverLimit unknowns, minres above
};

/// Unknowns above which `automatic` picks the iterative solver. Measured on
/// 2 cores with tools/bench_increment (Newtonian block, time per Newton
/// iteration): 12k unknowns UMFPACK 0.87 s, MINRES (IC(0) variant) 0.92 s;
/// 45k unknowns UMFPACK 7.0 s (1.3 GB), MINRES 4.6 s (0.28 GB). Below the limit the direct
/// solver is kept for its robustness (indefinite or unsymmetric tangents).
inline constexpr int kDirectSolverLimit = 20000;

/// The concrete solver `kind` stands for at `unknowns` free unknowns.
LinearSolverKind resolve(LinearSolverKind kind, int unknowns);

LinearSolverKind linear_solver_kind(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(LinearSolverKind kind);

class LinearSolver {
public:
  /// `component[i]` of free unknown i: 0, 1, 2 velocity x, y, z; 3 pressure (used by minres).
  LinearSolver(LinearSolverKind kind, std::vector<char> component);
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
  /// Iterations of the last iterative solve (0 for direct solvers).
  int iterations() const { return iterations_; }

private:
  struct Backend;
  LinearSolverKind kind_;
  std::unique_ptr<Backend> backend_;
  bool analysed_ = false;
  int analyses_ = 0;
  int iterations_ = 0;
};

} // namespace anvil::solver
