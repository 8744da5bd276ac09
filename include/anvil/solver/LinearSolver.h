// The linear solve of each Newton iteration (docs/design.md §2): the condensed
// system, symmetric quasi-definite, with contact rows. The default is the
// PETSc Krylov solver with the block preconditioner (KrylovSolver), near
// linear in the mesh size; MUMPS through PETSc is the direct option and the
// fallback when the Krylov method stagnates; SuiteSparse and Eigen solvers
// stay selectable for comparison.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"
#include "anvil/solver/KeptSetUp.h"
#include "anvil/solver/KrylovSolver.h"

#include <memory>
#include <optional>
#include <string>

namespace anvil::solver {

enum class LinearSolverKind {
  fgmres,       ///< PETSc FGMRES, block preconditioner: AMG on velocity, Schur with M_p/η (KrylovSolver)
  mumps,        ///< MUMPS through PETSc: LDLᵀ (LU when unsymmetric) (MumpsSolver)
  umfpack,      ///< SuiteSparse UMFPACK LU (for comparison)
  cholmod_ldlt, ///< SuiteSparse CHOLMOD simplicial LDLᵀ (no pivoting; quasi-definite only)
  eigen_ldlt,   ///< Eigen SimplicialLDLT with AMD (no pivoting; quasi-definite only)
  minres,       ///< Eigen MINRES, block-diagonal preconditioner (BlockPreconditioner; for comparison)
  automatic,    ///< mumps up to kDirectSolverLimit unknowns, fgmres above (mumps if it stagnates)
};

/// Unknowns up to which `automatic` picks the direct solver: the crossover
/// measured on 2 cores (docs/linear-solve.md). One increment from rest
/// (tools/bench_increment), MUMPS against FGMRES: Newtonian 0.11/0.14 s at
/// 3.7k unknowns, 0.30/0.35 s at 8.7k, 0.81/0.66 s at 16.8k; Norton-Hoff
/// m = 0.1 2.96/2.45 s at 4k, 6.84/7.08 s at 9k, 17.2/13.9 s at 17k. Whole
/// run of cases/upsetting.yaml (7.7k unknowns): 36.3/25.9 s.
inline constexpr int kDirectSolverLimit = 5000;

/// The concrete solver `kind` stands for at `unknowns` unknowns.
LinearSolverKind resolve(LinearSolverKind kind, int unknowns);

LinearSolverKind linear_solver_kind(const std::string& name); ///< throws InputError on an unknown name
std::string to_string(LinearSolverKind kind);
SchurApproximation schur_approximation(const std::string& name); ///< throws InputError on an unknown name

struct LinearSolverSettings {
  LinearSolverKind kind = LinearSolverKind::automatic;
  SchurApproximation schur = SchurApproximation::bfbt; ///< fgmres
  /// Keep the Krylov preconditioner across Newton iterations and increments
  /// while it pays: set it up again once the Krylov iterations the kept
  /// set-up has cost beyond a fresh one's (at the iterations per decade of
  /// residual reduction right after the last set-up) add up to
  /// `setup_cost` iterations, after a long Newton step (newton_step), when a
  /// solve fails, or when the pattern changes.
  bool reuse_preconditioner = true;
  /// A set-up's cost in Krylov iterations (ML and BFBT on the Norton-Hoff
  /// block: 16 at 13k nodes, 19 at 53k; `anvil_bench norton_hoff N fgmres
  /// --no-reuse`, set-up time over time per iteration). Counted, not timed,
  /// so that a run stays the same from one run to the next.
  double setup_cost = 16.0;
  /// What the scene tells the velocity AMG (facet contact between bodies,
  /// rotations only contact holds).
  VelocityBlockHints velocity_block{};
};

class LinearSolver {
public:
  /// `unknowns`: the problem's unknowns, for `automatic`; `partition`: the
  /// rows of each process; `timers`: where the PETSc solvers time the
  /// creation of their matrix, "matrix pattern" (both must outlive the
  /// solver). Several processes solve with fgmres or mumps only: InputError
  /// for the others.
  LinearSolver(const LinearSolverSettings& settings, int unknowns, const fem::Partition& partition, Timers& timers);
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  /// Prepares solves with `a`: factorises it (direct) or sets up or keeps
  /// the preconditioner (fgmres). `a` must stay in place until the next
  /// call (PETSc reads it without a copy). False when a factorisation fails.
  bool factorize(const fem::SparseMatrix& a, const SaddlePointData& data);
  /// x = A⁻¹ b; an iterative solve stops at `relative_tolerance` × |b|. When
  /// FGMRES stagnates the solver falls back to MUMPS for good (logged).
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance);
  /// The pattern of the next matrix differs (direct solvers analyse it again).
  void pattern_changed() { analysed_ = false; }
  /// The next matrix is another operator than the last (the law's tangent
  /// after the predictor's Newtonian stand-in): a kept preconditioner is set
  /// up again.
  void operator_changed() { refresh_ = true; }
  /// Newton moved the velocity by `relative_change` (|Δv|/|v|) since the
  /// last factorize(): beyond kLongNewtonStep a kept preconditioner is set
  /// up again at the next one.
  void newton_step(double relative_change);
  /// Back to the state of a new solver: no kept preconditioner, no MUMPS
  /// fallback. The run restarts its solver after each periodic checkpoint, as
  /// a run resumed from it starts with a new one, so both solve the next
  /// increment alike (a kept preconditioner changes an inexact solve); a
  /// checkpoint written at a stop carries the kept one instead (KeptSetUp).
  /// The Krylov solver keeps its matrix: the pattern holds no numbers.
  void restart();
  /// The preconditioner the first factorize() after the last accepted
  /// increment kept or would keep, as this process holds it, for a
  /// checkpoint written at a stop (KeptSetUp; gather_kept collects the
  /// processes'); empty when it sets up anew anyway, or saying that MUMPS
  /// had taken over.
  KeptSetUp kept_set_up() const;
  /// The run resumes from a checkpoint that carried `kept` (gathered): the
  /// first factorize() sets the preconditioner up from its entries and keeps
  /// it, as the uninterrupted run kept its own, unless a process's pattern
  /// is not the one they were taken on (every process then sets up anew,
  /// logged). A record of MUMPS's takeover makes MUMPS solve from the start.
  void resume_with(KeptSetUp kept);
  /// An increment was accepted: kept_set_up() describes the solver as it
  /// is now until the next call, whatever the next increment does to it.
  void increment_ended();

  /// The solver in use (mumps after a fallback).
  LinearSolverKind kind() const { return kind_; }
  bool iterative() const { return kind_ == LinearSolverKind::fgmres || kind_ == LinearSolverKind::minres; }
  int analyses() const { return analyses_; }
  /// The last solve ran on a preconditioner set up before its factorize().
  bool kept_preconditioner() const { return reused_; }
  /// Iterations of the last solve (0 for direct solvers).
  int iterations() const { return iterations_; }
  /// Preconditioner set-ups (fgmres) or factorisations (direct) so far.
  int setups() const { return setups_; }

private:
  /// Hands `a` to the Krylov solver, its preconditioner kept (`reuse`) or set up anew.
  void set_krylov_operator(const fem::SparseMatrix& a, const SaddlePointData& data, bool reuse);
  /// factorize() of the first tangent after a resume (resuming_): false when
  /// the kept set-up does not fit `a` and a new one is due.
  bool set_up_as_resumed(const fem::SparseMatrix& a, const SaddlePointData& data);
  /// FGMRES stagnated: MUMPS solves for the rest of this mesh.
  void take_over_direct();

  struct Backend;
  LinearSolverSettings settings_;
  int unknowns_;
  const fem::Partition& partition_;
  Timers& timers_;
  LinearSolverKind kind_;
  std::unique_ptr<Backend> backend_;
  const fem::SparseMatrix* matrix_ = nullptr; ///< of the last factorize(), for a fallback
  std::optional<SaddlePointData> data_;       ///< of the last factorize()
  bool analysed_ = false;
  int analyses_ = 0;
  int iterations_ = 0;
  int setups_ = 0;
  double setup_rate_ = 0.0;       ///< iterations per decade in the first solve after the last set-up
  double extra_iterations_ = 0.0; ///< beyond setup_rate_'s, over the solves on the kept set-up
  bool refresh_ = true;           ///< the next factorize() sets the preconditioner up again
  bool reused_ = false;           ///< the last factorize() kept an earlier preconditioner
  /// What a set-up was made from (kept_set_up).
  struct SetUpSource {
    std::vector<double> entries; ///< the tangent's, in its order
    double pattern = 0.0;        ///< pattern_hash of the tangent
    std::vector<mesh::Point> nodes;
    std::vector<double> pressure_mass;
  };
  /// The solver as the last accepted increment left it (increment_ended):
  /// a Ctrl-C abandons an increment part-way, and the checkpoint is of the
  /// state before it.
  struct Boundary {
    bool kept = false;     ///< the next factorize() would keep the set-up in use
    bool replaced = false; ///< a set-up since: boundary_source_ holds the kept one's source
    bool direct = false;   ///< MUMPS had taken over
    double setup_rate = 0.0, extra_iterations = 0.0;
  };
  SetUpSource source_;          ///< of the set-up in use
  SetUpSource boundary_source_; ///< of the set-up kept at the boundary, once another replaced it
  Boundary boundary_;
  bool resuming_ = false; ///< a checkpoint's set-up came with the resume: the first factorize() tries it
};

} // namespace anvil::solver
