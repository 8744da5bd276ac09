#include "anvil/solver/MumpsSolver.h"

#include "petsc_check.h"
#include "petsc_matrix.h"

#include <petscksp.h>

namespace anvil::solver {

using petsc::check;

struct MumpsSolver::Impl {
  Impl(const fem::Partition& p, Timers& timers) : matrix(p, timers), rhs(p), solution(p) {}
  petsc::MatrixView matrix;
  petsc::VectorSlot rhs, solution;
  KSP ksp = nullptr;
  int symmetric = -1; ///< of the factorisation in place: 1 LDLᵀ, 0 LU, −1 none
  ~Impl() { KSPDestroy(&ksp); }
};

MumpsSolver::MumpsSolver(const fem::Partition& partition, Timers& timers)
    : impl_(std::make_unique<Impl>(partition, timers)) {}
MumpsSolver::~MumpsSolver() = default;

bool MumpsSolver::factorize(const fem::SparseMatrix& a) {
  Impl& s = *impl_;
  const bool fresh = s.matrix.wrap(a);
  Mat m = s.matrix.mat();
  // Symmetric to round-off of the largest entry: LDLᵀ reads one triangle only.
  PetscReal largest = 0.0;
  check(MatNorm(m, NORM_MAX, &largest), "checking the tangent's symmetry");
  PetscBool symmetric = PETSC_FALSE;
  check(MatIsSymmetric(m, 1e-13 * largest, &symmetric), "checking the tangent's symmetry");
  check(MatSetOption(m, MAT_SYMMETRIC, symmetric), "checking the tangent's symmetry");
  if (fresh || s.symmetric != static_cast<int>(symmetric)) {
    KSPDestroy(&s.ksp);
    check(KSPCreate(PETSC_COMM_WORLD, &s.ksp), "creating the direct solver");
    check(KSPSetOptionsPrefix(s.ksp, "direct_"), "creating the direct solver");
    check(KSPSetType(s.ksp, KSPPREONLY), "creating the direct solver");
    PC pc = nullptr;
    check(KSPGetPC(s.ksp, &pc), "creating the direct solver");
    check(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU), "creating the direct solver");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "creating the direct solver");
    petsc::check_options(KSPSetFromOptions(s.ksp));
    s.symmetric = static_cast<int>(symmetric);
    ++analyses_;
  }
  check(KSPSetOperators(s.ksp, m, m), "factorising the tangent (MUMPS)");
  check(KSPSetUp(s.ksp), "factorising the tangent (MUMPS)");
  PC pc = nullptr;
  check(KSPGetPC(s.ksp, &pc), "factorising the tangent (MUMPS)");
  PCFailedReason failed = PC_NOERROR;
  check(PCGetFailedReason(pc, &failed), "factorising the tangent (MUMPS)");
  return failed == PC_NOERROR;
}

void MumpsSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  Impl& s = *impl_;
  x.setZero(b.size());
  check(KSPSolve(s.ksp, s.rhs.in(b), s.solution.in(x)), "solving with the MUMPS factors");
  s.solution.out(x);
}

} // namespace anvil::solver
