#include "anvil/solver/MumpsSolver.h"

#include "petsc_check.h"
#include "petsc_matrix.h"

#include "anvil/core/log.h"

#include <petscksp.h>

#include <algorithm>

namespace anvil::solver {

using petsc::check;

namespace {

/// Several processes: a system of at most this many unknowns is factorised
/// whole by each process alone (sequential MUMPS on a copy of the matrix).
/// MUMPS across processes picks the processes that share a front by their
/// load as it goes, so its sums, and the run after them, change from one
/// run to the next (upsetting_75 on 2 processes: four runs from one
/// checkpoint, four different meshes at the next remesh); alone, the
/// factorisation is the same every time. The copies cost each process the
/// whole factor's memory, which the bound keeps small: the direct solver of
/// `auto` stops at 5000 unknowns; above the bound (MUMPS taking over from a
/// stagnating Krylov solve on a large mesh) the processes share the factor.
constexpr PetscInt kWholeOnEachProcessUpTo = 50000;

} // namespace

struct MumpsSolver::Impl {
  Impl(const fem::Partition& p, Timers& timers) : partition(p), matrix(p, timers), rhs(p), solution(p) {}
  const fem::Partition& partition;
  petsc::MatrixView matrix;
  petsc::VectorSlot rhs, solution;
  Mat whole = nullptr;          ///< each process's copy of the whole matrix (kWholeOnEachProcessUpTo)
  Vec whole_solution = nullptr; ///< and of the solution
  KSP ksp = nullptr;
  int symmetric = -1;     ///< of the factorisation in place: 1 LDLᵀ, 0 LU, −1 none
  PetscInt workspace = 0; ///< ICNTL(14), % added to MUMPS's workspace estimate; 0: MUMPS's default
  ~Impl() {
    KSPDestroy(&ksp);
    MatDestroy(&whole);
    VecDestroy(&whole_solution);
  }
};

namespace {

/// MUMPS's errors of a workspace too small for the factorisation (INFOG(1):
/// −8 integer, −9 real, −11 and −12 for the solution, −14 integer again).
bool workspace_too_small(PetscInt infog1) {
  return infog1 == -8 || infog1 == -9 || infog1 == -11 || infog1 == -12 || infog1 == -14;
}

/// A new KSP of one factorisation by MUMPS (LDLᵀ or LU), options read.
KSP new_direct_solver(bool symmetric, MPI_Comm comm) {
  KSP ksp = nullptr;
  check(KSPCreate(comm, &ksp), "creating the direct solver");
  check(KSPSetOptionsPrefix(ksp, "direct_"), "creating the direct solver");
  check(KSPSetType(ksp, KSPPREONLY), "creating the direct solver");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "creating the direct solver");
  check(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU), "creating the direct solver");
  check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "creating the direct solver");
  petsc::check_options(KSPSetFromOptions(ksp));
  return ksp;
}

} // namespace

MumpsSolver::MumpsSolver(const fem::Partition& partition, Timers& timers, int workspace_percent)
    : impl_(std::make_unique<Impl>(partition, timers)) {
  impl_->workspace = workspace_percent;
}

int MumpsSolver::workspace_percent() const {
  return static_cast<int>(impl_->workspace);
}
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
  PetscInt rows = 0;
  check(MatGetSize(m, &rows, nullptr), "copying the tangent");
  if (s.partition.distributed() && rows <= kWholeOnEachProcessUpTo) {
    if (fresh) { // a new pattern: new copies, of its size
      MatDestroy(&s.whole);
      VecDestroy(&s.whole_solution);
    }
    check(MatCreateRedundantMatrix(m, s.partition.processes, MPI_COMM_NULL,
                                   s.whole ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s.whole),
          "copying the tangent to each process");
    check(MatSetOption(s.whole, MAT_SYMMETRIC, symmetric), "copying the tangent to each process");
    m = s.whole;
  } else {
    MatDestroy(&s.whole);
    VecDestroy(&s.whole_solution);
  }
  bool renew = fresh || s.symmetric != static_cast<int>(symmetric);
  // MUMPS sizes its workspace from the analysis; the delayed pivots of an
  // indefinite saddle-point matrix, more of them across several processes,
  // can need more than that (measured: upsetting_75 after a remesh, 2
  // processes, INFOG(1) = −9). The MUMPS users' guide's remedy is a larger
  // ICNTL(14): doubled, and the factorisation done again, up to four times;
  // it stays raised while the mesh does (restarts of the solver included).
  for (int attempt = 0;; ++attempt) {
    if (renew) {
      KSPDestroy(&s.ksp);
      s.ksp = new_direct_solver(symmetric, PetscObjectComm(reinterpret_cast<PetscObject>(m)));
      s.symmetric = static_cast<int>(symmetric);
      ++analyses_;
    }
    check(KSPSetOperators(s.ksp, m, m), "factorising the tangent (MUMPS)");
    PC pc = nullptr;
    check(KSPGetPC(s.ksp, &pc), "factorising the tangent (MUMPS)");
    if (renew && s.workspace > 0) {
      Mat factor = nullptr;
      check(PCFactorSetUpMatSolverType(pc), "factorising the tangent (MUMPS)");
      check(PCFactorGetMatrix(pc, &factor), "factorising the tangent (MUMPS)");
      check(MatMumpsSetIcntl(factor, 14, s.workspace), "factorising the tangent (MUMPS)");
    }
    check(KSPSetUp(s.ksp), "factorising the tangent (MUMPS)");
    PCFailedReason failed = PC_NOERROR;
    check(PCGetFailedReason(pc, &failed), "factorising the tangent (MUMPS)");
    if (failed == PC_NOERROR) return true;
    Mat factor = nullptr;
    PetscInt infog1 = 0, percent = 0;
    check(PCFactorGetMatrix(pc, &factor), "factorising the tangent (MUMPS)");
    check(MatMumpsGetInfog(factor, 1, &infog1), "factorising the tangent (MUMPS)");
    if (!workspace_too_small(infog1) || attempt == 4) return false;
    check(MatMumpsGetIcntl(factor, 14, &percent), "factorising the tangent (MUMPS)");
    s.workspace = 2 * std::max<PetscInt>(percent, 20);
    log::info("    MUMPS: workspace too small (INFOG(1) = %d); ICNTL(14) raised from %d to %d %% and the tangent "
              "factorised again",
              static_cast<int>(infog1), static_cast<int>(percent), static_cast<int>(s.workspace));
    renew = true;
  }
}

void MumpsSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  Impl& s = *impl_;
  x.setZero(b.size());
  if (!s.whole) {
    check(KSPSolve(s.ksp, s.rhs.in(b), s.solution.in(x)), "solving with the MUMPS factors");
    s.solution.out(x);
    return;
  }
  s.rhs.in(b);
  const Vec whole_rhs = s.rhs.gathered();
  if (!s.whole_solution) check(VecDuplicate(whole_rhs, &s.whole_solution), "solving with the MUMPS factors");
  check(KSPSolve(s.ksp, whole_rhs, s.whole_solution), "solving with the MUMPS factors");
  s.solution.read_whole(s.whole_solution, x);
}

} // namespace anvil::solver
