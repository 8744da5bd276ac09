// The iterative solve of the condensed MINI system on PETSc (docs/design.md §2,
// docs/linear-solve.md): flexible GMRES, right-preconditioned by the upper
// block factorisation
//   P = [ K̂  Bᵀ ]      K̂ ≈ K: one algebraic-multigrid V-cycle on the
//       [ 0  Ŝ  ]      velocity block (ML by default, aggregating on the
//                      nodes' geometry for facet contact, with the six
//                      rigid-body modes where only contact holds a
//                      rotation; GAMG with the rigid-body near-null space,
//                      or hypre BoomerAMG),
//   Ŝ ≈ S = −C − B K⁻¹ Bᵀ: stabilised BFBT by default (bfbt_schur.h), or
// −(C + M_p/η), the condensed-bubble block plus the lumped viscosity-scaled
// pressure mass (Elman, Silvester, Wathen 2014, §9.2), with the sign of the
// true Schur complement (the wrong sign costs 6x the iterations). The
// velocity and pressure splits are given as index sets (the C block defeats
// PETSc's saddle-point detection). Every choice is a PETSc option default,
// so -ksp_*, -pc_fieldsplit_*, -fieldsplit_0_* and -fieldsplit_1_* options
// on the command line or in solver.petsc_options override it.
#pragma once
#include "anvil/core/Timers.h"
#include "anvil/fem/Assembler.h"

#include <limits>
#include <memory>
#include <span>
#include <string>

namespace anvil::solver {

/// What the preconditioner needs besides the matrix.
struct SaddlePointData {
  std::span<const mesh::Point> nodes;   ///< current coordinates (rigid-body modes), mm
  const Eigen::VectorXd& pressure_mass; ///< M_p/η lumped per node (Assembler::pressure_mass)
  std::span<const int> parts;           ///< per node, its body (mesh::connected_parts); empty: one body
};

/// How the pressure block of the preconditioner approximates the Schur complement.
enum class SchurApproximation {
  bfbt, ///< stabilised BFBT (bfbt_schur.h): follows squeeze-flow (lubrication) pressure modes
  mass, ///< −(C + M_p/η): the condensed-bubble block and the viscosity-scaled pressure mass
};

/// What the velocity block's AMG is told about the scene.
struct VelocityBlockHints {
  /// Facet contact between bodies couples a node weakly with many nodes of
  /// the other body: ML aggregates on a distance Laplacian of the nodes (its
  /// auxiliary matrix) instead of the block's own couplings, and smooths with SOR.
  bool facet_contact = false;
  /// A body's conditions leave a rotation free, so that only its contact
  /// holds it: ML aggregates with the six rigid-body modes, not only the
  /// three translations, whose aggregates cannot represent the rotation.
  bool free_rotations = false;
};

struct KrylovOutcome {
  bool converged = false;
  int iterations = 0;
  double reduction = 1.0; ///< final residual norm / |b|
  std::string reason;     ///< PETSc's converged or diverged reason
};

class KrylovSolver {
public:
  /// On the rows of `partition`; the matrix's creation timed in `timers`
  /// (both must outlive the solver); the velocity AMG chosen after `hints`.
  KrylovSolver(SchurApproximation schur, VelocityBlockHints hints, const fem::Partition& partition, Timers& timers);
  ~KrylovSolver();
  KrylovSolver(const KrylovSolver&) = delete;
  KrylovSolver& operator=(const KrylovSolver&) = delete;

  /// Takes the tangent `a` (a view, no copy: `a` must stay in place until
  /// the next call). With `reuse`, the preconditioner of an earlier call is
  /// kept (the same pattern is required); otherwise it is set up again.
  void set_operator(const fem::SparseMatrix& a, const SaddlePointData& data, bool reuse);
  /// Takes `a` as set_operator does, with its preconditioner set up from
  /// other `entries` in a's pattern and order (a kept set-up a checkpoint
  /// carried, KeptSetUp); the next set_operator with `reuse` keeps it.
  void set_up_from(const fem::SparseMatrix& a, std::span<const double> entries, const SaddlePointData& data);
  /// Back to a new solver's state on the same matrix: the Krylov solver and
  /// its preconditioner are made anew at the next set_operator; the matrix
  /// and its pattern are kept.
  void restart();
  /// x = A⁻¹ b to `relative_tolerance` of |b| (x's start value is ignored),
  /// not converged after `max_iterations` or the solver's own limit (500, or
  /// -ksp_max_it), whichever is fewer.
  KrylovOutcome solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance,
                      int max_iterations = std::numeric_limits<int>::max());
  /// Preconditioner set-ups so far.
  int setups() const { return setups_; }

private:
  /// Sets the preconditioner up from the matrix in place.
  void set_up(const SaddlePointData& data);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  int setups_ = 0;
};

} // namespace anvil::solver
