#include "anvil/solver/LinearSolver.h"

#include "anvil/core/error.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/UmfPackSupport>

namespace anvil::solver {

struct LinearSolver::Backend {
  Eigen::UmfPackLU<fem::SparseMatrix> umfpack;
  Eigen::CholmodSimplicialLDLT<fem::SparseMatrix, Eigen::Lower> cholmod;
  Eigen::SimplicialLDLT<fem::SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<long>> eigen;
};

LinearSolverKind linear_solver_kind(const std::string& name) {
  if (name == "umfpack") return LinearSolverKind::umfpack;
  if (name == "cholmod_ldlt") return LinearSolverKind::cholmod_ldlt;
  if (name == "eigen_ldlt") return LinearSolverKind::eigen_ldlt;
  throw InputError("unknown linear solver '" + name + "' (expected umfpack, cholmod_ldlt or eigen_ldlt)");
}

std::string to_string(LinearSolverKind kind) {
  switch (kind) {
  case LinearSolverKind::umfpack: return "umfpack";
  case LinearSolverKind::cholmod_ldlt: return "cholmod_ldlt";
  case LinearSolverKind::eigen_ldlt: return "eigen_ldlt";
  }
  return "?";
}

LinearSolver::LinearSolver(LinearSolverKind kind) : kind_(kind), backend_(std::make_unique<Backend>()) {}
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
  }
  return false;
}

bool LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  switch (kind_) {
  case LinearSolverKind::umfpack: x = backend_->umfpack.solve(b); return backend_->umfpack.info() == Eigen::Success;
  case LinearSolverKind::cholmod_ldlt: x = backend_->cholmod.solve(b); return backend_->cholmod.info() == Eigen::Success;
  case LinearSolverKind::eigen_ldlt: x = backend_->eigen.solve(b); return backend_->eigen.info() == Eigen::Success;
  }
  return false;
}

} // namespace anvil::solver
