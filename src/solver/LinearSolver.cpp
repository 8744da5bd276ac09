#include "anvil/solver/LinearSolver.h"

#include "anvil/core/error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>
#include <unsupported/Eigen/IterativeSolvers>

#include "anvil/solver/BlockPreconditioner.h"

namespace anvil::solver {

struct LinearSolver::Backend {
  Eigen::UmfPackLU<fem::SparseMatrix> umfpack;
  Eigen::CholmodSimplicialLDLT<fem::SparseMatrix, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<fem::SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<long>> eigen;
  Eigen::MINRES<fem::SparseMatrix, Eigen::Lower | Eigen::Upper, BlockPreconditioner> minres;
};

LinearSolverKind linear_solver_kind(const std::string& name) {
  if (name == "umfpack") return LinearSolverKind::umfpack;
  if (name == "cholmod_ldlt") return LinearSolverKind::cholmod_ldlt;
  if (name == "eigen_ldlt") return LinearSolverKind::eigen_ldlt;
  if (name == "minres") return LinearSolverKind::minres;
  if (name == "auto") return LinearSolverKind::automatic;
  throw InputError("unknown linear solver '" + name + "' (expected auto, umfpack, cholmod_ldlt, eigen_ldlt or minres)");
}

std::string to_string(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::umfpack: return "umfpack";
  case LinearSolverKind::cholmod_ldlt: return "cholmod_ldlt";
  case LinearSolverKind::eigen_ldlt: return "eigen_ldlt";
  case LinearSolverKind::minres: return "minres";
  case LinearSolverKind::automatic: return "auto";
  }
  return "?";
}

LinearSolverKind resolve(LinearSolverKind kind, int unknowns) {
  if (kind != LinearSolverKind::automatic) return kind;
  return unknowns > kDirectSolverLimit ? LinearSolverKind::minres : LinearSolverKind::umfpack;
}

LinearSolver::LinearSolver(LinearSolverKind kind, std::vector<char> component)
    : kind_(resolve(kind, static_cast<int>(component.size()))), backend_(std::make_unique<Backend>()) {
  // Relative residual 1e-10: two orders below Newton's default tolerance, so
  // the inexact solve does not spoil Newton's quadratic convergence.
  backend_->minres.setTolerance(1e-10);
  backend_->minres.setMaxIterations(20000);
  backend_->minres.preconditioner().set_components(std::move(component));
}
LinearSolver::~LinearSolver() = default;

namespace {
template <class Solver> bool factorize_with(Solver& s, const fem::SparseMatrix& a, bool& analysed, int& analyses) {
  if (!analysed) {
    s.analyzePattern(a);
    analysed = true;
    ++analyses;
  }
  s.factorize(a);
  return s.info() == Eigen::Success;
}
} // namespace

bool LinearSolver::factorize(const fem::SparseMatrix& a) {
  switch (kind_) {
  case LinearSolverKind::umfpack: return factorize_with(backend_->umfpack, a, analysed_, analyses_);
  case LinearSolverKind::cholmod_ldlt: return factorize_with(backend_->cholmod, a, analysed_, analyses_);
  case LinearSolverKind::eigen_ldlt: return factorize_with(backend_->eigen, a, analysed_, analyses_);
  case LinearSolverKind::minres: backend_->minres.compute(a); return backend_->minres.info() == Eigen::Success;
  case LinearSolverKind::automatic: break; // resolved in the constructor
  }
  return false;
}

bool LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  switch (kind_) {
  case LinearSolverKind::umfpack: x = backend_->umfpack.solve(b); return backend_->umfpack.info() == Eigen::Success;
  case LinearSolverKind::cholmod_ldlt: x = backend_->cholmod.solve(b); return backend_->cholmod.info() == Eigen::Success;
  case LinearSolverKind::eigen_ldlt: x = backend_->eigen.solve(b); return backend_->eigen.info() == Eigen::Success;
  case LinearSolverKind::minres:
    x = backend_->minres.solve(b);
    iterations_ = static_cast<int>(backend_->minres.iterations());
    return backend_->minres.info() == Eigen::Success;
  case LinearSolverKind::automatic: break;
  }
  return false;
}

} // namespace anvil::solver
