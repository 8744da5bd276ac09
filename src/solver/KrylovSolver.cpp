#include "anvil/solver/KrylovSolver.h"

#include "anvil/core/interrupt.h"
#include "anvil/solver/PetscSession.h"
#include "bfbt_schur.h"
#include "held_modes.h"
#include "petsc_check.h"
#include "petsc_matrix.h"

#include <ml_utils.h>
#include <petscksp.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace anvil::solver {

using petsc::check;

namespace {

/// PETSc's default convergence test, and a stop after a SIGINT or SIGTERM
/// (core/interrupt): a long solve is abandoned within one Krylov iteration.
/// The check is collective, as the residual norm before it.
PetscErrorCode converged_unless_interrupted(KSP ksp, PetscInt it, PetscReal norm, KSPConvergedReason* reason,
                                            void* context) {
  PetscErrorCode error = KSPConvergedDefault(ksp, it, norm, reason, context);
  if (error == 0 && *reason == KSP_CONVERGED_ITERATING && interrupt::requested()) *reason = KSP_DIVERGED_BREAKDOWN;
  return error;
}

/// The seed ML gives itself at its first random vector in a process
/// (ML_random_vec: spread over [1, 2³¹ − 2] by rank).
int ml_initial_seed() {
  PetscMPIInt rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const int largest = 2147483647;
  return static_cast<int>((largest - 1) * (1.0 - (rank + 1) / (size + 1.0)));
}

/// ML's options for geometric aggregation (VelocityBlockHints::facet_contact).
/// Facet contact between bodies couples a node with the nodes of every
/// facet of the other body its facets overlap, many and each weakly where a
/// coarse facet lies on a fine mesh: aggregates that follow those couplings
/// cost the Krylov solve up to 2.6 times nodal contact's iterations on the
/// patch meshes. ML's auxiliary matrix, a Laplacian of the distances
/// between the nodes that drops couplings weaker than the threshold,
/// aggregates on the geometry instead (0.05 took as few facet iterations
/// as 0.02 and 0.1 or fewer on every patch pair, docs/linear-solve.md). PETSc reads
/// these options with the repartitioning's, which acts on several processes
/// only.
constexpr const char* kGeometricAggregation =
    "-fieldsplit_0_pc_ml_repartition true -fieldsplit_0_pc_ml_Aux true -fieldsplit_0_pc_ml_AuxThreshold 0.05";
/// ML's velocity levels with facet contact between bodies: Chebyshev
/// preconditioned by SOR, a symmetric sweep through each process's rows,
/// rather than point-block Jacobi. On the patch meshes it took about two
/// thirds of the iterations in about the same solve time, where with
/// point-block Jacobi facet contact took up to twice nodal contact's
/// (docs/linear-solve.md); with nodal contact alone it took fewer
/// iterations but more time, and nodal contact keeps point-block Jacobi.
constexpr const char* kFacetSmoothing = "-fieldsplit_0_mg_levels_pc_type sor";

/// How far apart ML sees two bodies, per body index, as a share of the
/// scene's extent: enough that coinciding nodes of two bodies get a finite
/// weight, far too little to change which couplings are strong. At 1e-4 the
/// patch pairs' and hertz_cylinder's Krylov iterations were those of the
/// bodies in place; further apart they changed (1e-2: fewer on most patch
/// pairs, more on hertz_cylinder; 10 extents, every aggregate in one body:
/// 1.1-5.5 times the iterations).
constexpr double kBodiesApart = 1e-4;

/// Whether the boolean option `name` is given and true.
bool option_is_true(const char* name) {
  PetscBool value = PETSC_FALSE;
  petsc::check_options(PetscOptionsGetBool(nullptr, nullptr, name, &value, nullptr));
  return value;
}

/// The solver of split `i` (0: velocity, 1: the Schur complement) of the
/// Schur fieldsplit `pc`, which owns it.
KSP split_solver(PC pc, int i, const char* doing) {
  PetscInt splits = 0;
  KSP* sub = nullptr;
  check(PCFieldSplitSchurGetSubKSP(pc, &splits, &sub), doing);
  KSP solver = sub[i];
  PetscFree(sub);
  return solver;
}
} // namespace

struct KrylovSolver::Impl {
  Impl(SchurApproximation s, VelocityBlockHints h, const fem::Partition& p, Timers& timers)
      : schur(s), hints(h), partition(p), matrix(p, timers), rhs(p), solution(p) {}
  SchurApproximation schur;
  VelocityBlockHints hints;
  const fem::Partition& partition;
  std::optional<petsc::BfbtSchur> bfbt; ///< of the KSP in place (its Schur PC's context)
  petsc::MatrixView matrix;
  petsc::VectorSlot rhs, solution;
  KSP ksp = nullptr;
  IS velocity = nullptr, pressure = nullptr;
  Mat schur_preconditioner = nullptr; ///< mass: Ŝ = A11 − diag(M_p/η)
  Vec pressure_mass = nullptr;
  Vec coordinates = nullptr;
  std::vector<PetscReal> ml_points;        ///< this process's nodes as ML aggregates them (ml_points_at)
  std::optional<PetscReal> user_tolerance; ///< -ksp_rtol's: it replaces the Newton-driven tolerance
  PetscInt max_iterations = 0;             ///< after the options (500, or -ksp_max_it)
  bool set_up = false;                     ///< the splits' solvers exist
  bool velocity_ml = false;                ///< ML on the velocity block (not an expert's GAMG or hypre)
  bool ml_coordinates = false;             ///< ML aggregates on the geometry: it needs the coordinates
  bool sor_smoothing = false;              ///< ML's velocity levels smoothed with SOR (kFacetSmoothing)

  ~Impl() { destroy(); }
  void destroy() {
    KSPDestroy(&ksp);
    bfbt.reset();
    ISDestroy(&velocity);
    ISDestroy(&pressure);
    MatDestroy(&schur_preconditioner);
    VecDestroy(&pressure_mass);
    VecDestroy(&coordinates);
  }

  /// KSP, splits and the vectors of a new matrix: this process's rows.
  void create() {
    destroy();
    set_up = false;
    const int nodes = partition.owned_count(), first = partition.first;
    std::vector<PetscInt> velocity_dofs(3 * static_cast<std::size_t>(nodes));
    for (int i = 0; i < nodes; ++i)
      for (int c = 0; c < 3; ++c)
        velocity_dofs[3 * static_cast<std::size_t>(i) + c] = fem::kDofsPerNode * (first + i) + c;
    check(ISCreateGeneral(PETSC_COMM_WORLD, 3 * nodes, velocity_dofs.data(), PETSC_COPY_VALUES, &velocity),
          "creating the velocity split");
    check(ISSetBlockSize(velocity, 3), "creating the velocity split"); // x, y, z of a node: one AMG block
    check(ISCreateStride(PETSC_COMM_WORLD, nodes, fem::kDofsPerNode * first + 3, fem::kDofsPerNode, &pressure),
          "creating the pressure split");
    const PetscInt all = static_cast<PetscInt>(partition.node.size());
    check(VecCreateMPI(PETSC_COMM_WORLD, nodes, all, &pressure_mass), "creating a vector");
    check(VecCreateMPI(PETSC_COMM_WORLD, 3 * nodes, 3 * all, &coordinates), "creating a vector");
    check(VecSetBlockSize(coordinates, 3), "creating a vector");

    // Nested solvers read their options when the preconditioner is set up:
    // anvil's choices go in as defaults that the user's options override.
    set_default_option("-fieldsplit_0_ksp_type", "preonly");
    set_default_option("-fieldsplit_0_pc_type", "ml");
    // ML aggregates with the modes set_near_null_space gives it.
    set_default_option("-fieldsplit_0_pc_ml_nullspace", "user");
    // Chebyshev smooths every ML level (velocity and BFBT's pressure
    // Laplacian): more Krylov iterations than PETSc's default (two SOR
    // sweeps), each about half the price, cheaper overall (docs/linear-solve.md).
    // On the velocity levels it is preconditioned by the inverse of each
    // node's 3×3 block: a contact node's penalty ρA n nᵀ couples its three
    // components wherever the die's normal is not along an axis (a drafted
    // wall, a fillet), which scalar Jacobi does not see. In a closed die's
    // flash, where that penalty dominates the node's row, scalar Jacobi took
    // 3.2 times the Krylov iterations. With ML only: the coarse levels of an
    // expert's GAMG carry six rigid-body modes a node, blocks that pbjacobi
    // failed to invert on the patch-test cubes; GAMG keeps Jacobi. Facet
    // contact between bodies smooths with SOR instead (kFacetSmoothing).
    set_default_option("-fieldsplit_0_mg_levels_ksp_type", "chebyshev");
    char velocity_amg[32] = "";
    petsc::check_options(
        PetscOptionsGetString(nullptr, nullptr, "-fieldsplit_0_pc_type", velocity_amg, sizeof velocity_amg, nullptr));
    velocity_ml = std::string(velocity_amg) == "ml";
    set_default_option("-fieldsplit_0_mg_levels_pc_type", velocity_ml ? "pbjacobi" : "jacobi");
    sor_smoothing = velocity_ml && hints.facet_contact;
    // An expert's -fieldsplit_0_pc_ml_Aux decides; else the scene's contact.
    PetscBool aux_given = PETSC_FALSE;
    petsc::check_options(PetscOptionsHasName(nullptr, nullptr, "-fieldsplit_0_pc_ml_Aux", &aux_given));
    ml_coordinates = velocity_ml && (aux_given ? option_is_true("-fieldsplit_0_pc_ml_Aux") : hints.facet_contact);
    set_default_option("-fieldsplit_1_bfbt_mg_levels_ksp_type", "chebyshev");
    set_default_option("-fieldsplit_1_bfbt_mg_levels_pc_type", "jacobi");
    set_default_option("-fieldsplit_1_ksp_type", "preonly");
    set_default_option("-fieldsplit_1_bfbt_pc_type", "ml");

    check(KSPCreate(PETSC_COMM_WORLD, &ksp), "creating the Krylov solver");
    check(KSPSetType(ksp, KSPFGMRES), "creating the Krylov solver"); // the AMG cycle varies: flexible
    check(KSPGMRESSetRestart(ksp, 100), "creating the Krylov solver");
    check(KSPSetTolerances(ksp, 1e-6, PETSC_DEFAULT, PETSC_DEFAULT, 500), "creating the Krylov solver");
    PC pc = nullptr;
    check(KSPGetPC(ksp, &pc), "creating the preconditioner");
    check(PCSetType(pc, PCFIELDSPLIT), "creating the preconditioner");
    check(PCFieldSplitSetIS(pc, "0", velocity), "creating the preconditioner");
    check(PCFieldSplitSetIS(pc, "1", pressure), "creating the preconditioner");
    check(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "creating the preconditioner");
    check(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_UPPER), "creating the preconditioner");
    if (schur == SchurApproximation::bfbt) {
      // PETSc forms L = B D⁻¹ Bᵀ + C (as −selfp) for BfbtSchur, with D K's
      // node blocks as in BFBT's middle term (bfbt_schur.h says why).
      check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_SELFP, nullptr), "creating the preconditioner");
      set_default_option("-fieldsplit_1_mat_schur_complement_ainv_type", "blockdiag");
    }
    petsc::check_options(KSPSetFromOptions(ksp));
    void* converged = nullptr;
    check(KSPConvergedDefaultCreate(&converged), "creating the Krylov solver");
    check(KSPSetConvergenceTest(ksp, converged_unless_interrupted, converged, KSPConvergedDefaultDestroy),
          "creating the Krylov solver");
    PetscReal tolerance = 0.0;
    check(KSPGetTolerances(ksp, &tolerance, nullptr, nullptr, &max_iterations), "creating the Krylov solver");
    PetscBool given = PETSC_FALSE;
    petsc::check_options(PetscOptionsHasName(nullptr, nullptr, "-ksp_rtol", &given));
    if (given) user_tolerance = tolerance;
  }

  /// Gives ML the velocity nodes' coordinates (this process's, packed by
  /// node) before its set-up, for aggregation on the geometry. ML forgets
  /// them whenever it is set up again (its reset): `again` resets it first,
  /// on its operators, so that its next set-up is a first one and keeps them.
  void give_ml_coordinates(KSP velocity_ksp, bool again) {
    PC ml = nullptr;
    check(KSPGetPC(velocity_ksp, &ml), "giving the velocity AMG the coordinates");
    if (again) {
      Mat a = nullptr, p = nullptr;
      check(PCGetOperators(ml, &a, &p), "giving the velocity AMG the coordinates");
      check(PetscObjectReference(reinterpret_cast<PetscObject>(a)), "giving the velocity AMG the coordinates");
      check(PetscObjectReference(reinterpret_cast<PetscObject>(p)), "giving the velocity AMG the coordinates");
      check(PCReset(ml), "giving the velocity AMG the coordinates");
      check(PCSetOperators(ml, a, p), "giving the velocity AMG the coordinates");
      MatDestroy(&a);
      MatDestroy(&p);
    }
    check(PCSetCoordinates(ml, 3, static_cast<PetscInt>(ml_points.size() / 3), ml_points.data()),
          "giving the velocity AMG the coordinates");
  }

  /// The owned nodes at `data`'s coordinates, each body moved along x by
  /// its index times kBodiesApart of the scene's extent. ML's auxiliary
  /// matrix weighs a coupling by 1/d², d the distance between its nodes, and
  /// a contact pair couples nodes of two bodies that can coincide (the line
  /// of first contact of a cylinder on a block, the corners of non-matching
  /// cubes), where ML took 1/0 and printed the nodes on stdout.
  void ml_points_at(const SaddlePointData& data) {
    const double apart = kBodiesApart * mesh::bounding_box(data.nodes).diagonal().norm();
    ml_points.resize(3 * static_cast<std::size_t>(partition.owned_count()));
    for (int i = 0; i < partition.owned_count(); ++i) {
      const int node = partition.node[partition.first + i];
      const int part = data.parts.empty() ? 0 : data.parts[node];
      for (int c = 0; c < 3; ++c)
        ml_points[3 * static_cast<std::size_t>(i) + c] = data.nodes[node][c] + (c == 0 ? part * apart : 0.0);
    }
  }

  /// Builds the splits' preconditioners now (the multigrid hierarchies), not
  /// at the first application, so the set-up is timed as such.
  void set_up_splits(PC pc, bool first) {
    PetscInt splits = 0;
    KSP* sub = nullptr;
    check(PCFieldSplitSchurGetSubKSP(pc, &splits, &sub), "setting up the preconditioner");
    if (first && ml_coordinates) give_ml_coordinates(sub[0], false);
    for (PetscInt i = 0; i < splits; ++i)
      check(KSPSetUp(sub[i]), "setting up the preconditioner");
    PetscFree(sub);
  }

  /// The Schur complement's PC, once its KSP exists (after the first
  /// set-up): BfbtSchur, or Jacobi on Ŝ, unless an expert chose one with
  /// -fieldsplit_1_pc_type. Set here, not as an option default, because two
  /// solvers of one process may approximate the Schur complement differently.
  void choose_schur_pc(PC pc) {
    PetscBool given = PETSC_FALSE;
    petsc::check_options(PetscOptionsHasName(nullptr, nullptr, "-fieldsplit_1_pc_type", &given));
    if (given) return;
    PC schur_pc = nullptr;
    check(KSPGetPC(split_solver(pc, 1, "setting up the Schur preconditioner"), &schur_pc),
          "setting up the Schur preconditioner");
    if (schur == SchurApproximation::bfbt)
      bfbt.emplace().attach(schur_pc);
    else
      check(PCSetType(schur_pc, PCJACOBI), "setting up the Schur preconditioner");
  }

  /// The velocity block's near-null space at the current coordinates and
  /// the entries of `system`, less the directions a penalty holds
  /// (held_directions.h): the three translations, or the six rigid-body
  /// modes on a body only its dies hold in rotation (elsewhere the six make
  /// ML's set-up and V-cycle dearer for about one Krylov iteration less,
  /// docs/linear-solve.md) and for an expert's GAMG. ML's with
  /// `-fieldsplit_0_pc_ml_nullspace user` (the default), GAMG's; hypre uses
  /// the block size.
  void set_near_null_space(std::span<const mesh::Point> nodes, Mat system) {
    constexpr const char* doing = "setting the velocity block's near-null space";
    PetscScalar* x = nullptr;
    check(VecGetArray(coordinates, &x), doing);
    for (int i = 0; i < partition.owned_count(); ++i)
      for (int c = 0; c < 3; ++c)
        x[3 * i + c] = nodes[partition.node[partition.first + i]][c];
    check(VecRestoreArray(coordinates, &x), doing);
    MatNullSpace modes =
        petsc::held_rigid_body_modes(system, coordinates, velocity_ml && !hints.free_rotations ? 3 : 6);
    check(PetscObjectCompose(reinterpret_cast<PetscObject>(velocity), "nearnullspace",
                             reinterpret_cast<PetscObject>(modes)),
          doing);
    // After the first set-up the split's matrix exists: it takes the new modes directly.
    PC pc = nullptr;
    check(KSPGetPC(ksp, &pc), doing);
    PetscInt splits = 0;
    KSP* sub = nullptr;
    if (set_up) {
      check(PCFieldSplitGetSubKSP(pc, &splits, &sub), doing);
      Mat velocity_block = nullptr;
      check(KSPGetOperators(sub[0], nullptr, &velocity_block), doing);
      if (velocity_block) check(MatSetNearNullSpace(velocity_block, modes), doing);
      PetscFree(sub);
    }
    check(MatNullSpaceDestroy(&modes), doing);
  }
};

KrylovSolver::KrylovSolver(SchurApproximation schur, VelocityBlockHints hints, const fem::Partition& partition,
                           Timers& timers)
    : impl_(std::make_unique<Impl>(schur, hints, partition, timers)) {}
KrylovSolver::~KrylovSolver() = default;

void KrylovSolver::restart() {
  impl_->destroy();
}

void KrylovSolver::set_operator(const fem::SparseMatrix& a, const SaddlePointData& data, bool reuse) {
  Impl& s = *impl_;
  const bool made = s.matrix.wrap(a) || !s.ksp; // a new matrix, or a restart: a new KSP
  if (made) s.create();
  if (reuse && !made) {
    check(KSPSetReusePreconditioner(s.ksp, PETSC_TRUE), "reusing the preconditioner");
    return;
  }
  set_up(data);
}

void KrylovSolver::set_up_from(const fem::SparseMatrix& a, std::span<const double> entries,
                               const SaddlePointData& data) {
  Impl& s = *impl_;
  if (s.matrix.wrap(a) || !s.ksp) s.create();
  // On one process the Mat reads a's own array: its entries are put back after.
  const std::vector<double> own(a.valuePtr(), a.valuePtr() + a.nonZeros());
  s.matrix.put(entries);
  set_up(data);
  s.matrix.put(own);
}

void KrylovSolver::set_up(const SaddlePointData& data) {
  Impl& s = *impl_;
  Mat m = s.matrix.mat();
  PC pc = nullptr;
  check(KSPGetPC(s.ksp, &pc), "building the preconditioner");
  if (s.schur == SchurApproximation::mass) {
    // Ŝ = A11 − M_p/η: the assembled pressure block (−C) plus the mass part.
    check(MatCreateSubMatrix(m, s.pressure, s.pressure, s.schur_preconditioner ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX,
                             &s.schur_preconditioner),
          "building the Schur-complement preconditioner");
    PetscScalar* mass = nullptr;
    check(VecGetArray(s.pressure_mass, &mass), "building the Schur-complement preconditioner");
    for (int i = 0; i < s.partition.owned_count(); ++i)
      mass[i] = -data.pressure_mass[s.partition.node[s.partition.first + i]];
    check(VecRestoreArray(s.pressure_mass, &mass), "building the Schur-complement preconditioner");
    check(MatDiagonalSet(s.schur_preconditioner, s.pressure_mass, ADD_VALUES),
          "building the Schur-complement preconditioner");
    check(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, s.schur_preconditioner),
          "building the preconditioner");
  }
  // An expert's -pc_fieldsplit_schur_precondition (a11, selfp, ...) still wins.
  petsc::check_options(PCSetFromOptions(pc));
  s.set_near_null_space(data.nodes, m);
  check(KSPSetOperators(s.ksp, m, m), "setting up the preconditioner");
  check(KSPSetReusePreconditioner(s.ksp, PETSC_FALSE), "setting up the preconditioner");
  // ML draws random vectors (its eigenvalue estimates) from one global seed
  // that every set-up advances: reset, each set-up is that of a fresh
  // process, so a resumed run and a second run in the same process solve as
  // the first did.
  ML_set_random_seed(ml_initial_seed());
  const bool first = !s.set_up;
  // For this solver's first set-up only, where its sub-solvers read their
  // options: another solver of the process (the test programs, a chain's
  // next operation) must not read them, and ML keeps what it read.
  std::optional<ScopedPetscOptions> geometric;
  if (first && s.ml_coordinates) geometric.emplace(kGeometricAggregation, "anvil's geometric aggregation");
  // At every set-up: ML builds its levels, and their smoothers read their
  // options, again at each one.
  std::optional<ScopedPetscOptions> smoothing;
  if (s.sor_smoothing) smoothing.emplace(kFacetSmoothing, "anvil's smoothing for facet contact");
  if (s.ml_coordinates) {
    s.ml_points_at(data);
    if (!first) s.give_ml_coordinates(split_solver(pc, 0, "setting up the preconditioner"), true);
  }
  check(KSPSetUp(s.ksp), "setting up the preconditioner");
  if (first) s.choose_schur_pc(pc);
  s.set_up = true;
  s.set_up_splits(pc, first);
  ++setups_;
}

KrylovOutcome KrylovSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance,
                                  int max_iterations) {
  Impl& s = *impl_;
  check(KSPSetTolerances(s.ksp, s.user_tolerance.value_or(relative_tolerance), PETSC_DEFAULT, PETSC_DEFAULT,
                         std::min<PetscInt>(max_iterations, s.max_iterations)),
        "setting the Krylov tolerance");
  x.setZero(b.size());
  check(KSPSolve(s.ksp, s.rhs.in(b), s.solution.in(x)), "solving the linear system");
  s.solution.out(x);
  KrylovOutcome out;
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(s.ksp, &iterations), "reading the Krylov iterations");
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(s.ksp, &reason), "reading the Krylov outcome");
  PetscReal residual = 0.0;
  check(KSPGetResidualNorm(s.ksp, &residual), "reading the Krylov outcome");
  const double norm = b.norm();
  out.reduction = norm > 0.0 ? residual / norm : 0.0;
  out.iterations = static_cast<int>(iterations);
  out.converged = reason > 0;
  out.reason = KSPConvergedReasons[reason];
  return out;
}

} // namespace anvil::solver
